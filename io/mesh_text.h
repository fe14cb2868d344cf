#pragma once
// Pieces shared by the triangle and tet mesh readers.
#include <Eigen/Core>
#include <fstream>
#include <istream>
#include <string>
#include <vector>

#include "akvf/mesh.h"
#include "akvf/obj_passthrough.h"

namespace akvf {

// Upper bound on what a header count may make a reader reserve before the
// data is seen; larger meshes grow their vectors as rows arrive.
constexpr long long kMaxReserve = 1 << 20;

// Vertex coordinates and element corner indices as read, row by row.
struct RawElements {
  std::vector<double> coords;       // 3 per vertex
  std::vector<int> corners;         // the elements' corners one after another, 0-based
  std::vector<int> sizes;           // per element, its number of corners
  std::vector<double> texture;      // `vt` u v, 2 per row
  std::vector<int> corner_texture;  // per corner the `vt` row (0-based); -1 none, -2 no such row
};

// The OBJ `v` / `f` records with exactly `corners` indices per `f`, or at
// least three for corners == 3 (polygons, for the caller to triangulate)
// (`a`, `a/b`, `a//c`, `a/b/c`, negative = relative). A `v` has x y z, an
// optional weight w, or x y z r g b (colour); other counts are refused. The
// other statements OBJ allows (vt vn vp g o s usemtl mtllib l p) are skipped;
// any other statement is skipped with one warning per kind. `element` names
// the elements in messages ("face", "tet"); `advice` follows a wrong corner
// count. `passthrough` (if given) receives what the file carries besides.
RawElements read_obj_elements(std::istream& in, const std::string& file_name, int corners, const std::string& element,
                              const std::string& advice, Warnings* warnings, ObjPassthrough* passthrough = nullptr);

// Row-major rows to an Eigen matrix with `Cols` columns.
template <class Scalar, int Cols>
Eigen::Matrix<Scalar, Eigen::Dynamic, Cols> rows_to_matrix(const std::vector<Scalar>& values) {
  using RowMajor = Eigen::Matrix<Scalar, Eigen::Dynamic, Cols, Eigen::RowMajor>;
  return Eigen::Map<const RowMajor>(values.data(), static_cast<Eigen::Index>(values.size() / Cols), Cols);
}

// ".obj" for "dir/Cow.OBJ"; "" without an extension.
std::string lowercase_extension(const std::string& path);

// Opens a mesh file for reading; InputError naming it if that fails.
std::ifstream open_mesh_file(const std::string& path);

}  // namespace akvf
