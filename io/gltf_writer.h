#pragma once
// `akvf param --out UV.glb`: binary glTF 2.0 (one file: JSON chunk + binary
// chunk) with the surface, its texture coordinates and the checkerboard
// embedded as a PNG, so any glTF viewer (Blender, three.js, the browsers'
// model viewers) shows the checker on the surface.
#include <Eigen/Core>
#include <string>

#include "akvf/mesh.h"
#include "io/png_image.h"

namespace akvf {

// glTF has no per-corner attributes: a vertex is written once per distinct
// UV it has (seam vertices twice or more). Positions and UVs as 32-bit
// floats (OutputError if a coordinate does not fit); UV v is flipped to
// glTF's top-left texture origin. Written atomically.
//   UV        #T by 2 (the texture's unit square: unit_square_uv)
//   UV_faces  #F by 3 rows of UV
void write_glb(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& UV_faces,
               const RgbImage& texture);

}  // namespace akvf
