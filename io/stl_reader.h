#pragma once
// STL triangle soups, ASCII and binary, welded into an indexed mesh.
//
// STL stores every facet's three corners by value. Corners closer than the
// weld tolerance become one vertex. The tolerance is 4 float32 ulps of the
// bounding box's diagonal (4 * 2^-23 * diagonal, about 5e-7 of it), because
// binary STL rounds every coordinate to float32 and writers that compute a
// shared corner twice may differ by a rounding or two; but at most a tenth
// of the shortest facet edge, so a weld never joins two corners of one
// facet nor shortens an edge by more than a fifth (a plate thinner than the
// diagonal's ulps keeps its two sides). Anything farther apart is a
// different point. Vertices are numbered by first appearance. Binary is
// recognized by its size (84 + 50 n bytes for n facets), not by the first
// word, since many binary files also begin with "solid". Errors name the
// file and the line (ASCII) or the facet (binary).
#include <istream>
#include <string>

#include "akvf/mesh.h"

namespace akvf {

// The weld tolerance relative to the bounding-box diagonal, and its bound
// relative to the shortest facet edge.
constexpr double kStlWeldTolerance = 4.0 / (1 << 23);
constexpr double kStlWeldEdgeFraction = 0.1;

TriMesh read_stl(std::istream& in, const std::string& file_name);

}  // namespace akvf
