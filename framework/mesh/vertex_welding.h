#pragma once
// Exact duplicate vertices welded across pieces (akvf param --repair
// auto): a triangle soup, or a model whose parts were exported apart, has
// several vertices at one position in separate pieces (faces joined
// across shared edges), and the surface falls apart into as many charts. Such
// a vertex's corners move to the first vertex at its position (coordinates
// equal bit for bit, as libigl's remove_duplicate_vertices with epsilon 0)
// when the two lie in different pieces, joining them; twins within one
// piece are the file's own seams (the two sides of a cut disk) and stay
// apart. The vertices themselves stay, so the input's numbering is kept.
#include <string>
#include <vector>

#include "akvf/mesh.h"

namespace akvf {

struct VertexWelding {
  int welded = 0;                 // vertices whose corners moved to a twin in another piece
  std::vector<int> first_welded;  // the first few of them (0-based)
};

// *welded: `mesh` with its corners moved (V unchanged), set only when a
// vertex was welded.
VertexWelding weld_exact_duplicates(const TriMesh& mesh, TriMesh* welded);

// The welding in words, for a warning, numbered as the file numbers
// vertices.
std::string welding_description(const VertexWelding& welding, const std::string& name, int index_base);

}  // namespace akvf
