#pragma once
// Seams added to charts that are already disks (`--cut seams`): a path of
// interior edges from an interior vertex to the chart's boundary, and the
// chart opened along it (a slit: the chart stays a disk, its boundary loop
// now running down one side of the path and back up the other).
#include <string>
#include <vector>

#include "akvf/mesh.h"
#include "framework/mesh/mesh_validation.h"

namespace akvf {

// What `--cut seams` did.
struct SeamReport {
  int seams = 0;                         // paths opened after the first cut (seam_paths)
  double seam_length = 0;                // every opened edge's 3D length over the square root of the area
  std::vector<double> chart_distortion;  // per chart: symmetric Dirichlet energy of its final map
  bool bound_met = false;                // every chart at most max_distortion
  std::string stop_reason;               // why seams stopped before the bound held (empty if it held)
};

// Per start in turn, the shortest path (3D edge lengths) from it to its
// chart's boundary or to an earlier path, through vertices on neither:
// start, ..., an end vertex. A start on the boundary or an earlier path has
// none (it is left out). The paths form trees, each meeting the boundary at
// one vertex, so that opening them leaves every chart a disk.
std::vector<std::vector<int>> seam_paths(const TriMesh& mesh, const std::vector<int>& starts);

// Opens `disk` along the edges of `paths` (seam_paths'): its mesh,
// input_vertex, boundary_loops, cut_edges, cut_length and the sources of the
// corners set aside are updated; faces keep their order. Returns, for every
// new vertex, the vertex of the old mesh it copies (ascending).
std::vector<int> open_seams(DiskMesh* disk, const std::vector<std::vector<int>>& paths);

// Opens `disk` along every edge between faces of different charts of
// `face_chart` (num_charts charts, each a disk: a partition that refines
// disk->face_chart), which becomes its face_chart; updated and returned as
// open_seams does.
std::vector<int> split_charts(DiskMesh* disk, const std::vector<int>& face_chart, int num_charts);

}  // namespace akvf
