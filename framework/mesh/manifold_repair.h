#pragma once
// Input that other tools accept, made manifold for the parameterization
// (akvf param --repair auto): edges shared by three or more faces opened,
// and every vertex split into one copy per fan of faces that meet it
// (libigl's split_nonmanifold does the same). A manifold mesh is left as it
// is. The
// faces keep their order; the copies keep their input vertex, so the outputs
// (per-corner UV) keep the input's numbering.
#include <array>
#include <string>
#include <utility>
#include <vector>

#include "akvf/mesh.h"

namespace akvf {

struct ManifoldRepair {
  int opened_edges = 0;    // edges shared by three or more faces
  int split_vertices = 0;  // vertices whose faces form several fans
  int added_copies = 0;    // the copies those splits added
  // The first few of each, as input vertex indices (0-based).
  std::vector<int> first_split;
  std::vector<std::array<int, 2>> first_opened;

  bool any() const { return opened_edges + split_vertices > 0; }
};

// Repairs `mesh` in place; `input_vertex` (#V: each vertex's index in the
// input) grows with the copies. Two faces join across an edge when they are
// its only two faces, or, of an edge with more, the first two (in file
// order) that run along it in opposite directions; the corners of a vertex
// joined through such edges form one fan, and each fan after the first gets
// a copy of the vertex.
// Edges in `open` ((smaller, larger) vertex pairs, ascending) join no faces:
// the mesh is cut along them (orientation_with_cuts's cuts).
ManifoldRepair repair_manifold(TriMesh* mesh, std::vector<int>* input_vertex,
                               const std::vector<std::pair<int, int>>& open = {});

// The repairs in words, for a warning ("" when none), numbered as the file
// numbers vertices.
std::string repair_description(const ManifoldRepair& repair, const std::string& name, int index_base);

}  // namespace akvf
