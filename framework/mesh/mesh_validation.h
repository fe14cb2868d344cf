#pragma once
// Checks that a triangle mesh can be parameterized: finite, non-degenerate,
// edge-manifold, consistently oriented, one component, disk topology.
#include <string>
#include <vector>

#include "framework/mesh/mesh.h"

namespace akvf {

// A mesh ready for parameterization, with the map back to the input's
// vertex numbering (unreferenced input vertices are dropped).
struct DiskMesh {
  TriMesh mesh;                   // compacted: every vertex is used by a face
  std::vector<int> input_vertex;  // #mesh.V: index in the input mesh
  int num_input_vertices = 0;
  std::vector<int> boundary_loop;  // ordered, mesh to the left
  Warnings warnings;
};

// Validates `input` (read from `name`, used in messages) and drops
// unreferenced vertices with a warning. Throws ValidationError with a message
// that says what is wrong and what to do about it.
DiskMesh prepare_disk_mesh(const TriMesh& input, const std::string& name);

}  // namespace akvf
