#pragma once
// Mesh containers. Shapes follow libigl's convention.
#include <Eigen/Core>
#include <string>
#include <vector>

namespace akvf {

// A triangle mesh in R^3.
//   V  #V by 3 vertex positions
//   F  #F by 3 vertex indices (0-based), counter-clockwise seen from outside
struct TriMesh {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  // How the source numbers vertices and faces in messages: 1 for OBJ (and
  // MEDIT), 0 for OFF, .tet and arrays. Indices here are always 0-based.
  int index_base = 0;

  int num_vertices() const { return static_cast<int>(V.rows()); }
  int num_faces() const { return static_cast<int>(F.rows()); }
};

// The texture coordinates a triangle mesh file carries (OBJ `vt` per
// corner, PLY per-vertex u,v): rows of `uv`, and for every face corner the
// row it uses (-1 where a corner has none, -2 where its index names no row).
// Empty when the file has none.
struct MeshTexture {
  Eigen::MatrixXd uv;      // #T by 2
  Eigen::MatrixXi corner;  // #F by 3 rows of uv, or 0 rows
  bool empty() const { return corner.rows() == 0; }
};

// A tetrahedral mesh in R^3.
//   V  #V by 3 vertex positions
//   T  #T by 4 vertex indices (0-based), positively oriented after validation:
//      (x1 - x0) . ((x2 - x0) x (x3 - x0)) > 0
struct TetMesh {
  Eigen::MatrixXd V;
  Eigen::MatrixXi T;
  int index_base = 0;  // as TriMesh::index_base

  int num_vertices() const { return static_cast<int>(V.rows()); }
  int num_tets() const { return static_cast<int>(T.rows()); }
};

// Element or vertex i (0-based) as the source numbers it, and the note that
// says so once per message: "vertex 359 ... (numbered from 1, as in the file)"
// for OBJ and MEDIT, "(numbered from 0)" for OFF, .tet and arrays.
inline std::string file_number(long long i, int index_base) { return std::to_string(i + index_base); }
inline std::string numbering_note(int index_base) {
  return index_base == 0 ? " (numbered from 0)" : " (numbered from " + std::to_string(index_base) + ", as in the file)";
}

// Non-fatal findings of readers and validation, for the program to print.
using Warnings = std::vector<std::string>;

}  // namespace akvf
