#pragma once
// Seams added to charts that are already disks (`--cut seams`): a path of
// interior edges from an interior vertex to the chart's boundary, and the
// chart opened along it (a slit: the chart stays a disk, its boundary loop
// now running down one side of the path and back up the other).
#include <Eigen/Core>
#include <limits>
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
  int overlap_pieces = 0;                // charts added where a flip-free map that met the bound lay over itself
  int parted_charts = 0;                 // charts parted in two (split_through) to meet the bound
};

// Per start in turn, a path of interior edges that opens it (3D edge
// lengths): from an interior start, the shortest path to its chart's
// boundary or to an earlier path, through vertices on neither: start, ...,
// an end vertex; from a start on the boundary, the edge to its neighbour of
// highest `energy` (per vertex) on neither: that neighbour, start. A start
// on an earlier path, or on the boundary with no such neighbour, has none
// (it is left out). From a boundary start the path goes on, an edge at a
// time, to the neighbour of highest energy on neither while that energy is
// above `crease_walk_above` and the edge lies on a feature line (its faces'
// normals more than 30° apart, their other edges not), turning by less
// than 30° after its first such edge: a seam along a sharp edge is not
// seen, and the distortion of a rim (a cylinder's cap) lies all along it.
// The paths form trees, each meeting the boundary at one vertex, so that
// opening them leaves every chart a disk.
std::vector<std::vector<int>> seam_paths(const TriMesh& mesh, const std::vector<int>& starts,
                                         const std::vector<double>& energy,
                                         double crease_walk_above = std::numeric_limits<double>::infinity());

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

// Opens `disk` across each chart c with through[c] >= 0 along a path of
// interior edges from boundary to boundary through vertex through[c] (the
// 3D-shortest on either side of an interior vertex; from a boundary vertex,
// to the nearest other boundary vertex), its inner vertices interior, so
// that the chart parts into two disks: the first (with the chart's first
// face) keeps its number, the second is numbered after the charts. A chart
// with no such path (one triangle) stays whole. Updated and returned as
// open_seams does; *parted (if given) = the charts parted.
std::vector<int> split_through(DiskMesh* disk, const std::vector<int>& through, int* parted = nullptr);

// Each copy of an input vertex that lies within `fraction` (below 1) of its
// smallest triangle height of another copy in the map x (the two sides of
// a seam that has not opened, or barely) moved into its own triangles, so
// that the seam's sides no longer touch (global injectivity's boundary
// barrier is infinite where they do): by `fraction` of that height along
// the bisector of its inner angle on its boundary loop. Its own fan of
// triangles holds that segment (each triangle's height at the vertex is its
// distance to the opposite edge), so the copy flips none of its triangles,
// and in a map whose fans do not overlap, the copies, each moved into its
// own fan, do not cross each other.
void part_seam_sides(const DiskMesh& disk, double fraction, Eigen::VectorXd* x);

}  // namespace akvf
