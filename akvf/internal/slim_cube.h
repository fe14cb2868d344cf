#pragma once
// The SLIM paper's cube deformation (its libigl tutorial 709, reused in the
// AKVF paper's §6.2 and Figure 8): the vertices on the cube's four vertical
// edges (x and y both at their min or max) are constrained; the edge at
// (min x, min y) is rotated by +0.3 pi about the axis (1,1,0)/sqrt(2) through
// the edge's midpoint, the edge at (max x, max y) by -0.3 pi about the same
// axis through its own midpoint, and the other two edges are scaled by 0.75
// about the origin.
#include "akvf/constrained_objective.h"
#include "akvf/mesh.h"

namespace akvf {

// Throws ValidationError if the mesh has no vertices on those edges.
PositionConstraints slim_cube_constraints(const TetMesh& mesh);

}  // namespace akvf
