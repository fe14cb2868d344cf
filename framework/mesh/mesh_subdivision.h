#pragma once
// Midpoint (1-to-4) subdivision of a triangle mesh: every edge gets a vertex
// at its midpoint and every triangle becomes four. Topology (components,
// boundary loops, Euler characteristic) and the surface are unchanged; used
// to build the large meshes of the paper's Figure 6.
#include "akvf/mesh.h"

namespace akvf {

// `rounds` rounds (>= 0); faces grow by 4^rounds. Throws ValidationError if
// the result would exceed max_faces.
TriMesh subdivide_midpoint(const TriMesh& mesh, int rounds, long long max_faces = 100'000'000);

}  // namespace akvf
