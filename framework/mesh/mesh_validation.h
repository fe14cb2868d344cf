#pragma once
// Checks that a triangle mesh can be parameterized: finite, non-degenerate,
// edge-manifold, consistently oriented, one component, disk topology; or,
// with the automatic cut, any such manifold mesh cut into one disk (chart)
// per component.
#include <string>
#include <vector>

#include "akvf/mesh.h"
#include "framework/mesh/manifold_repair.h"
#include "framework/mesh/unusable_faces.h"
#include "framework/mesh/vertex_welding.h"

namespace akvf {

// A mesh ready for parameterization, with the map back to the input's
// vertex numbering (unreferenced input vertices are dropped).
struct DiskMesh {
  TriMesh mesh;                   // compacted (and cut): every vertex is used by a face; faces in the input's order
  std::vector<int> input_vertex;  // #mesh.V: index in the input mesh (seam copies share one)
  int num_input_vertices = 0;
  std::vector<std::vector<int>> boundary_loops;     // one per chart, in chart order; ordered, mesh to the left
  std::vector<int> face_chart;                      // #F: chart of each face (all 0 without a cut)
  bool cut = false;                                 // the automatic cut was asked for
  int cut_edges = 0;                                // input edges opened by it
  double cut_length = 0;                            // their total length
  std::vector<int> chart_genus, chart_input_loops;  // per chart, of its component before the cut
  ManifoldRepair repair;                            // what was repaired (repair asked for)
  VertexWelding welding;                            // duplicate vertices welded (repair asked for)
  // Faces set aside with repair (unusable_faces.h): mesh face i is input face
  // input_face[i] (empty: the same), and removed_faces are the others, their
  // corners' UVs taken from removed_corners.
  std::vector<int> input_face, removed_faces;
  std::vector<std::array<CornerSource, 3>> removed_corners;
  // Mesh faces whose second and third corners were swapped to agree with
  // their neighbours (repair asked for; face_orientation.h), ascending.
  std::vector<int> reoriented_faces;
  // A surface no winding makes agree, with cut and repair asked for: the
  // edges it was cut along where the windings disagree, as input vertex
  // pairs (face_orientation.h).
  std::vector<std::pair<int, int>> orientation_cuts;
  Warnings warnings;

  int num_charts() const { return static_cast<int>(boundary_loops.size()); }
  // Whether a vertex may have several UVs (seams of the cut, split
  // vertices): outputs then carry per-corner texture coordinates.
  bool per_corner_uv() const { return cut || repair.any() || welding.welded > 0 || !removed_faces.empty(); }
};

// Validates `input` (read from `name`, used in messages) and drops
// unreferenced vertices with a warning. With `repair`, exact duplicate
// vertices are welded (vertex_welding.h), degenerate and
// repeated faces set aside (unusable_faces.h), edges of three or more
// faces opened, non-manifold vertices split (manifold_repair.h) and faces
// wound against their neighbours reversed (face_orientation.h), each with
// a warning. With `cut`, a closed, multi-boundary, higher-genus or
// multi-component manifold mesh is cut into disks (cut_to_disk.h); without,
// it is refused with a message naming the option. Throws ValidationError
// with a message that says what is wrong and what to do about it.
DiskMesh prepare_disk_mesh(const TriMesh& input, const std::string& name, bool cut = false, bool repair = false);

// What the automatic cut did, in words: "cut into 2 charts along 40 edges
// (chart 0: genus 1, no boundary; chart 1: genus 0, 2 boundary loops)".
std::string cut_description(const DiskMesh& disk);

}  // namespace akvf
