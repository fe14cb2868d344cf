// write_mesh (akvf/mesh_io.h): one call for every mesh output format.
#include <filesystem>

#include "akvf/error.h"
#include "akvf/mesh_io.h"
#include "framework/process/output_file.h"
#include "io/checker_texture.h"
#include "io/gltf_writer.h"
#include "io/mesh_text.h"
#include "io/ply_reader.h"

namespace akvf {

namespace {

// The OBJ with its MTL and checkerboard: the side files go first; when the
// OBJ then fails, those this call created are removed with it.
void write_textured_obj(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& uv,
                        const Eigen::MatrixXi& uv_faces, const ObjPassthrough* source) {
  const TextureFiles files = texture_files_for(path);
  const bool mtl_existed = std::filesystem::exists(files.mtl), png_existed = std::filesystem::exists(files.png);
  try {
    write_checker_texture(files);
    write_obj_with_uv(path, mesh, unit_square_uv(uv), uv_faces, files.mtl_name, source);
  } catch (...) {
    std::error_code ignored;
    if (!mtl_existed) std::filesystem::remove(files.mtl, ignored);
    if (!png_existed) std::filesystem::remove(files.png, ignored);
    throw;
  }
}

}  // namespace

double write_mesh(const std::string& path, const TriMesh& mesh, const Eigen::MatrixXd& uv,
                  const Eigen::MatrixXi& uv_faces, const MeshWriteOptions& options) {
  if (options.texture != "checker" && options.texture != "none")
    throw OptionsError("texture must be checker or none, found '" + options.texture + "'");
  std::string kind = lowercase_extension(path);
  if (kind != ".obj" && kind != ".ply" && kind != ".glb") {
    if (!is_special_output(path))  // a device or FIFO (/dev/stdout) gets an OBJ
      throw OptionsError("cannot write " + path + ": the extension must be .obj, .ply or .glb");
    kind = ".obj";
  }
  const Eigen::MatrixXi& corners = uv_faces.size() == 0 ? mesh.F : uv_faces;
  check_corner_uv(mesh, uv, corners);
  const bool per_vertex = uv.rows() == mesh.V.rows() && corners == mesh.F;
  if (kind == ".glb") {
    write_glb(path, mesh, unit_square_uv(uv), corners, checker_image());
    return unit_square_scale(uv);
  }
  if (kind == ".ply") {
    if (per_vertex) {
      write_ply_with_uv(path, mesh, uv);
    } else {
      write_ply_with_uv(path, mesh, uv, corners);
    }
    return 0;
  }
  if (options.texture == "none") {
    write_obj_with_uv(path, mesh, uv, corners, "", options.obj_source);
    return 0;
  }
  write_textured_obj(path, mesh, uv, corners, options.obj_source);
  return unit_square_scale(uv);
}

}  // namespace akvf
