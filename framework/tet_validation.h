#pragma once
// Checks that a tet mesh can be deformed: finite coordinates, indices in
// range, no repeated corner, no degenerate tet, consistent orientation (a
// globally inverted file is flipped with a warning, mixed orientation is an
// error), one connected component.
#include <string>

#include "framework/mesh.h"

namespace akvf {

// Signed volume of tet t: (x1 - x0) . ((x2 - x0) x (x3 - x0)) / 6.
double signed_tet_volume(const TetMesh& mesh, int t);

// Returns the validated mesh (possibly with every tet's orientation flipped);
// throws ValidationError naming `name` and the problem.
TetMesh prepare_tet_mesh(const TetMesh& input, const std::string& name, Warnings* warnings);

}  // namespace akvf
