#pragma once
// Cutting a manifold triangle mesh into disks (`--cut auto`): closed meshes,
// meshes with several boundary loops, handles and several components.
//
// Per connected component, every boundary loop is closed by a cone on a
// virtual vertex (edges of length 0) so the surface is closed; a shortest-
// path tree T from a root (a cone vertex if there are loops) and a maximum
// dual spanning tree C of the edges outside T, weighted by the length of the
// loop each edge closes through T (Erickson and Whittlesey 2005: the greedy
// system of loops is the shortest through the root) leave 2g edges whose
// loops, with T, form a cut graph. Pruning its dangling branches, except at
// the cone vertices, leaves the 2g loops joined to every boundary loop along
// shortest paths. A closed genus-0 component keeps instead the tree path
// between two far-apart vertices (a double sweep of the tree distances).
// Opening the mesh along the real edges of that graph gives one disk per
// component: one boundary loop, Euler characteristic 1.
#include <vector>

#include "akvf/mesh.h"

namespace akvf {

struct DiskCut {
  TriMesh mesh;                    // the input's faces in their order; a seam vertex has one copy per side
  std::vector<int> source_vertex;  // #mesh.V: the input vertex each copies (ascending)
  std::vector<int> face_chart;     // #F: the chart (component) of each face, numbered by first face
  int num_charts = 0;
  int cut_edges = 0;             // input edges opened (each becomes two boundary edges)
  double cut_length = 0;         // their total length
  std::vector<int> chart_genus;  // #charts: genus of the component before cutting
  std::vector<int> chart_loops;  // #charts: its boundary loops before cutting
  int nonmanifold_vertex = -1;
};

// `mesh` must be edge-manifold, consistently oriented and without
// unreferenced vertices (mesh_validation.h checks all three). If a vertex is
// not manifold (its faces form two fans meeting at a point), the result is
// only nonmanifold_vertex, set to it.
DiskCut cut_to_disks(const TriMesh& mesh);

}  // namespace akvf
