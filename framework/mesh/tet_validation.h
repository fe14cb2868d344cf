#pragma once
// Checks that a tet mesh can be deformed: finite coordinates, indices in
// range, no repeated corner, no degenerate tet, consistent orientation (a
// globally inverted file is flipped with a warning, mixed orientation is an
// error), one connected component; vertices in no tet are dropped.
#include <string>
#include <vector>

#include "akvf/mesh.h"

namespace akvf {

// Signed volume of tet t: (x1 - x0) . ((x2 - x0) x (x3 - x0)) / 6.
double signed_tet_volume(const TetMesh& mesh, int t);

// A validated mesh ready for deformation, with the map back to the input's
// vertex numbering (vertices in no tet are dropped).
struct PreparedTetMesh {
  TetMesh mesh;                   // every vertex in a tet; orientation fixed if it was inverted
  std::vector<int> input_vertex;  // #mesh.V: index in the input mesh
  int num_input_vertices = 0;

  // The mesh in the input's numbering with positions X (#mesh.V by 3) for
  // the kept vertices and the input's positions for the dropped ones.
  TetMesh in_input_numbering(const Eigen::MatrixXd& X, const TetMesh& input) const;
};

// Validates `input`; drops unreferenced vertices and warns about repeated
// tets and coincident vertices (when `warnings` is given). Throws
// ValidationError naming `name`, the element as the file numbers it, and the
// problem.
PreparedTetMesh prepare_tet_mesh(const TetMesh& input, const std::string& name, Warnings* warnings);

}  // namespace akvf
