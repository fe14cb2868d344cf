#pragma once
// The textured OBJ of `akvf param --out UV.obj --texture checker`: UV.mtl
// (material "checker", diffuse map UV_checker.png) and the checkerboard PNG
// beside the OBJ, so MeshLab, Blender or ParaView show the checkerboard on
// the surface (the paper's Figure 9, first column).
#include <Eigen/Core>
#include <string>

#include "io/png_image.h"

namespace akvf {

struct TextureFiles {
  std::string mtl, png;            // paths beside the OBJ
  std::string mtl_name, png_name;  // as the OBJ and the MTL name them
};

// UV.obj -> UV.mtl and UV_checker.png in the same folder ("my uv.obj" ->
// my_uv.mtl, my_uv_checker.png: OBJ and MTL readers split names on spaces).
TextureFiles texture_files_for(const std::string& obj_path);

// A 1024-pixel image of 16 x 16 squares, grey 40 and 235.
RgbImage checker_image();

// Writes the MTL and the checker image as PNG.
void write_checker_texture(const TextureFiles& files);

// The layout scaled into the unit square (the texture's [0, 1]^2), keeping
// its aspect ratio: a texture repeats per unit of vt, so vt at the input's
// scale would show one square per unit of length, whatever the mesh's size.
// It is (UV - its lowest corner) * unit_square_scale(UV).
Eigen::MatrixXd unit_square_uv(const Eigen::MatrixXd& UV);
double unit_square_scale(const Eigen::MatrixXd& UV);

}  // namespace akvf
