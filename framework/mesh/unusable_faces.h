#pragma once
// Faces a parameterization cannot use, set aside before it (akvf param
// --repair auto): faces that use a vertex twice, faces of zero area (to
// working precision, relative to their own edges), and repeats of an earlier
// face (the same three vertices in any order). They keep UVs in the outputs:
// each corner takes its vertex's UV, and a vertex no other face uses takes
// one interpolated along the face (corner_sources).
#include <array>
#include <vector>

#include "akvf/mesh.h"

namespace akvf {

// Whether face f of `mesh` has zero area: below the rounding of the cross
// product of its edges (about eps |b - a| |c - a|), so slivers are kept
// whatever the mesh's size.
bool zero_area_face(const TriMesh& mesh, int f);

struct UnusableFaces {
  std::vector<int> kept;     // the other faces, in order
  std::vector<int> removed;  // in order
  int repeated_vertex = 0, zero_area = 0, repeated_face = 0;

  bool any() const { return !removed.empty(); }
};

UnusableFaces find_unusable_faces(const TriMesh& mesh);

// Where a removed face's corner takes its UV from: (1 - t) uv[a] + t uv[b] in
// the parameterized mesh's vertices; a == b (t = 0) for its own vertex, a < 0
// when no vertex of the face is parameterized ((0, 0)).
struct CornerSource {
  int a = -1, b = -1;
  double t = 0;
};

// The sources of the corners of `removed` (faces of `input`). input_vertex:
// each parameterized vertex's index in `input` (the first copy of a vertex
// serves). A vertex that only removed faces use is projected on the segment
// between the face's two other vertices when both are parameterized, else on
// the nearest one that is.
std::vector<std::array<CornerSource, 3>> corner_sources(const TriMesh& input, const std::vector<int>& removed,
                                                        const std::vector<int>& input_vertex);

}  // namespace akvf
