#pragma once
// Meshes built in code, for the demo and the tests (no files needed).
#include "akvf/mesh.h"

namespace akvf {

// The bent bar of Figure 2: a rectangle of `length` by `width`, sampled with
// nx by ny vertices, rolled onto a cylinder so its centre line bends through
// `bend_angle` radians. It is developable (isometric to the flat rectangle),
// so symmetric Dirichlet's minimum on it is exactly 4.
TriMesh bent_bar(int nx = 61, int ny = 11, double length = 6.0, double width = 1.0, double bend_angle = 3.0);

}  // namespace akvf
