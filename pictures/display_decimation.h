#pragma once
// Fewer faces for a picture of a large mesh (the HTML view): vertex
// clustering (Rossignac and Borrel 1993) on a uniform grid in space and in
// the texture plane, so seam copies (far apart in UV) stay apart.
#include <vector>

#include "io/seam_split_mesh.h"

namespace akvf {

struct DisplayMesh {
  SeamSplitMesh mesh;
  std::vector<int> source_face;  // #mesh.F: a face of the input that each face stands for
};

// At most max_faces faces (the input as it is when it has no more). A
// cluster's position and UV are its vertices' means; faces whose corners
// fall into fewer than three clusters are dropped. The cell size starts at
// sqrt(2 A / max_faces) for surface area A (a cell of area h^2 holds about
// two faces) and doubles until the count fits.
DisplayMesh decimate_for_display(const SeamSplitMesh& mesh, long long max_faces);

}  // namespace akvf
