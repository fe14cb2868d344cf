#include "framework/mesh/mesh_validation.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <cmath>
#include <numeric>

#include "akvf/error.h"
#include "framework/mesh/cut_to_disk.h"
#include "framework/mesh/face_orientation.h"
#include "framework/mesh/mesh_topology.h"
#include "framework/mesh/unusable_faces.h"

namespace akvf {

namespace {

// A face that uses a vertex twice is refused unless `repair` sets it aside.
void check_finite_and_indices(const TriMesh& m, const std::string& name, bool repair) {
  const int b = m.index_base;
  for (int v = 0; v < m.num_vertices(); ++v)
    if (!m.V.row(v).allFinite())
      throw ValidationError(name + ": vertex " + file_number(v, b) + " has a non-finite coordinate" +
                            numbering_note(b));
  for (int f = 0; f < m.num_faces(); ++f) {
    for (int k = 0; k < 3; ++k)
      if (m.F(f, k) < 0 || m.F(f, k) >= m.num_vertices())
        throw ValidationError(name + ": face " + file_number(f, b) + " has vertex index " + file_number(m.F(f, k), b) +
                              " out of range (" + std::to_string(m.num_vertices()) + " vertices)" + numbering_note(b));
    if (!repair && (m.F(f, 0) == m.F(f, 1) || m.F(f, 1) == m.F(f, 2) || m.F(f, 0) == m.F(f, 2)))
      throw ValidationError(name + ": face " + file_number(f, b) + " uses the same vertex twice (" +
                            file_number(m.F(f, 0), b) + ", " + file_number(m.F(f, 1), b) + ", " +
                            file_number(m.F(f, 2), b) + ")" + numbering_note(b));
  }
}

// The mesh of input's faces `kept`, without the vertices none of them uses
// (a warning names those no face of the file, `given`, uses: input's faces
// are given's, their corners perhaps moved by welding).
DiskMesh compact(const TriMesh& input, const std::vector<int>& kept, const std::string& name, const TriMesh& given) {
  DiskMesh out;
  out.num_input_vertices = input.num_vertices();
  std::vector<int> new_index(input.num_vertices(), -1);
  for (const int f : kept)
    for (int k = 0; k < 3; ++k) new_index[input.F(f, k)] = 0;
  std::vector<char> in_file(given.num_vertices(), 0);
  for (int f = 0; f < given.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) in_file[given.F(f, k)] = 1;
  int dropped = 0, first_dropped = -1;
  for (int v = 0; v < input.num_vertices(); ++v) {
    if (new_index[v] == 0) {
      new_index[v] = static_cast<int>(out.input_vertex.size());
      out.input_vertex.push_back(v);
    } else if (!in_file[v] && dropped++ == 0) {
      first_dropped = v;
    }
  }
  out.mesh.V.resize(static_cast<Eigen::Index>(out.input_vertex.size()), 3);
  for (std::size_t i = 0; i < out.input_vertex.size(); ++i) out.mesh.V.row(i) = input.V.row(out.input_vertex[i]);
  out.mesh.F.resize(static_cast<Eigen::Index>(kept.size()), 3);
  for (std::size_t i = 0; i < kept.size(); ++i)
    for (int k = 0; k < 3; ++k) out.mesh.F(i, k) = new_index[input.F(kept[i], k)];
  out.mesh.index_base = input.index_base;
  if (dropped > 0)
    out.warnings.push_back(name + ": dropped " + std::to_string(dropped) + " unreferenced vertices (first: " +
                           file_number(first_dropped, input.index_base) + numbering_note(input.index_base) +
                           "); no face uses their UV: (0, 0) where one per vertex is written at the input's scale "
                           "(the API's uv, PLY, --texture none)");
  return out;
}

void check_face_areas(const TriMesh& m, const std::string& name, const std::vector<int>& input_vertex) {
  const int base = m.index_base;
  auto at_input = [&](int v) { return file_number(input_vertex[v], base); };
  for (int f = 0; f < m.num_faces(); ++f)
    if (zero_area_face(m, f))
      throw ValidationError(name + ": face " + file_number(f, base) + " (vertices " + at_input(m.F(f, 0)) + ", " +
                            at_input(m.F(f, 1)) + ", " + at_input(m.F(f, 2)) + ") has zero area" +
                            numbering_note(base) + "; remove degenerate faces first (--repair auto sets them aside)");
}

// The faces set aside, in words, numbered as in the file.
std::string unusable_description(const UnusableFaces& unusable, const std::string& name, int base) {
  std::string kinds;
  const auto add = [&](int n, const char* what) {
    if (n > 0) kinds += (kinds.empty() ? "" : ", ") + std::to_string(n) + " " + what;
  };
  add(unusable.zero_area, "of zero area");
  add(unusable.repeated_face, "repeating an earlier face");
  add(unusable.repeated_vertex, "using a vertex twice");
  std::string first;
  const std::size_t listed = std::min<std::size_t>(unusable.removed.size(), 5);
  for (std::size_t i = 0; i < listed; ++i) first += (i ? ", " : "") + file_number(unusable.removed[i], base);
  const int n = static_cast<int>(unusable.removed.size());
  return name + ": set aside " + std::to_string(n) + (n == 1 ? " face" : " faces") + " the map cannot use (" + kinds +
         "; face" + (n == 1 ? " " : "s ") + first + (unusable.removed.size() > listed ? ", ..." : "") + ")" +
         numbering_note(base) +
         "; the outputs keep them, their corners at their vertices' UVs (--repair none refuses "
         "them)";
}

constexpr const char* kCutHint = " it must be cut to a disk first: use the option cut auto (akvf param --cut auto)";

void cut_into_charts(const std::string& name, DiskMesh* disk) {
  DiskCut cut = cut_to_disks(disk->mesh);
  const int b = disk->mesh.index_base;
  if (cut.nonmanifold_vertex >= 0)
    throw ValidationError(name + ": vertex " + file_number(disk->input_vertex[cut.nonmanifold_vertex], b) +
                          numbering_note(b) + " is non-manifold: its faces form separate fans that meet there");
  std::vector<int> input_vertex(cut.source_vertex.size());
  for (std::size_t v = 0; v < input_vertex.size(); ++v) input_vertex[v] = disk->input_vertex[cut.source_vertex[v]];
  disk->input_vertex = std::move(input_vertex);
  disk->mesh = std::move(cut.mesh);
  disk->face_chart = std::move(cut.face_chart);
  disk->cut = true;
  disk->cut_edges = cut.cut_edges;
  disk->cut_length = cut.cut_length;
  disk->chart_genus = std::move(cut.chart_genus);
  disk->chart_input_loops = std::move(cut.chart_loops);
}

// One component unless cut, and one boundary loop and Euler characteristic
// 1 per chart (a disk each), or the error that says which the mesh is not.
void find_chart_boundaries(const std::string& name, DiskMesh* disk) {
  const TriMesh& m = disk->mesh;
  const EdgeTopology topology = edge_topology(m.F);
  int charts = 0;
  const std::vector<int> chart_of = vertex_components(m.F, m.num_vertices(), &charts);
  if (!disk->cut && charts != 1)
    throw ValidationError(name + ": mesh has " + std::to_string(charts) +
                          " connected components; parameterize one disk-shaped component at a time, or all as "
                          "charts side by side with the option cut auto (akvf param --cut auto)");
  std::vector<std::vector<std::vector<int>>> loops(charts);
  for (auto& loop : boundary_loops(topology, m.num_vertices()))
    loops[chart_of[loop.front()]].push_back(std::move(loop));
  std::vector<long long> euler(charts, 0);
  for (int v = 0; v < m.num_vertices(); ++v) ++euler[chart_of[v]];
  // Edges = (3 F + boundary edges) / 2: an interior edge is in two faces.
  std::vector<long long> half_edges(charts, 0);
  for (int f = 0; f < m.num_faces(); ++f) {
    ++euler[chart_of[m.F(f, 0)]];
    half_edges[chart_of[m.F(f, 0)]] += 3;
  }
  for (const auto& [from, to] : topology.boundary_half_edges) ++half_edges[chart_of[from]];
  for (int c = 0; c < charts; ++c) euler[c] -= half_edges[c] / 2;
  for (int c = 0; c < charts; ++c) {
    const std::string where = charts == 1 ? "mesh" : "chart " + std::to_string(c);
    if (disk->cut && (loops[c].size() != 1 || euler[c] != 1))
      throw NumericalError(name + ": the automatic cut left " + where + " with " + std::to_string(loops[c].size()) +
                           " boundary loops and Euler characteristic " + std::to_string(euler[c]) +
                           " (a disk has 1 and 1); please report this mesh");
    if (loops[c].empty()) throw ValidationError(name + ": mesh is closed (no boundary loop);" + kCutHint);
    if (loops[c].size() > 1)
      throw ValidationError(name + ": mesh has " + std::to_string(loops[c].size()) +
                            " boundary loops (a disk has exactly one);" + kCutHint);
    if (euler[c] != 1)
      throw ValidationError(name + ": Euler characteristic is " + std::to_string(euler[c]) +
                            " (a disk has 1): the mesh has handles;" + kCutHint);
  }
  disk->boundary_loops.clear();
  for (auto& chart : loops) disk->boundary_loops.push_back(std::move(chart.front()));
  if (!disk->cut) disk->face_chart.assign(m.num_faces(), 0);
}

}  // namespace

DiskMesh prepare_disk_mesh(const TriMesh& given, const std::string& name, bool cut, bool repair) {
  if (given.num_faces() == 0) throw ValidationError(name + ": mesh has no faces");
  check_finite_and_indices(given, name, repair);
  // With repair, the faces on the welded vertices from here on.
  TriMesh welded;
  VertexWelding welding;
  if (repair) welding = weld_exact_duplicates(given, &welded);
  const TriMesh& input = welding.welded > 0 ? welded : given;
  UnusableFaces unusable;
  if (repair) {
    unusable = find_unusable_faces(input);
    if (unusable.kept.empty()) throw ValidationError(name + ": no face has an area (every face is degenerate)");
  } else {
    unusable.kept.resize(input.num_faces());
    std::iota(unusable.kept.begin(), unusable.kept.end(), 0);
  }
  DiskMesh out = compact(input, unusable.kept, name, given);
  out.welding = welding;
  if (welding.welded > 0) out.warnings.push_back(welding_description(welding, name, input.index_base));
  const TriMesh& m = out.mesh;
  const int b = m.index_base;
  auto at_input = [&](int v) { return file_number(out.input_vertex[v], b); };
  auto face_at_input = [&](int f) { return file_number(out.input_face.empty() ? f : out.input_face[f], b); };
  if (unusable.any()) {
    out.warnings.push_back(unusable_description(unusable, name, b));
    out.input_face = unusable.kept;
    out.removed_faces = unusable.removed;
  }
  check_face_areas(m, name, out.input_vertex);
  if (repair) {
    out.repair = repair_manifold(&out.mesh, &out.input_vertex);
    if (out.repair.any()) out.warnings.push_back(repair_description(out.repair, name, b));
  }

  EdgeTopology topology = edge_topology(m.F);
  if (!topology.overused_edge.empty())
    throw ValidationError(name + ": edge (" + at_input(topology.overused_edge[0]) + ", " +
                          at_input(topology.overused_edge[1]) + ") is shared by " +
                          std::to_string(topology.overused_edge[2]) + " faces" + numbering_note(b) +
                          "; the mesh must be edge-manifold");
  std::vector<char> flip;
  bool orientable = topology.misoriented_edge.empty() || consistent_orientation(m.F, &flip);
  if (repair && cut && !orientable) {
    // Cut where no winding agrees: the pieces are orientable, then cut into
    // disks like any other surface.
    std::vector<std::pair<int, int>> cuts;
    orientation_with_cuts(m.F, &flip, &cuts);
    out.reoriented_faces = reverse_faces(flip, &out.mesh.F);
    const int vertices = m.num_vertices();
    repair_manifold(&out.mesh, &out.input_vertex, cuts);
    for (const auto& [u, v] : cuts) out.orientation_cuts.push_back({out.input_vertex[u], out.input_vertex[v]});
    out.warnings.push_back(orientation_cut_description(out.orientation_cuts, m.num_vertices() - vertices,
                                                       out.reoriented_faces.size(), name, b));
    topology = edge_topology(m.F);
    orientable = true;
  } else if (repair && orientable && !topology.misoriented_edge.empty()) {
    out.reoriented_faces = reverse_faces(flip, &out.mesh.F);
    out.warnings.push_back(reorientation_description(out.reoriented_faces, out.input_face, name, b));
    topology = edge_topology(m.F);
  }
  if (!orientable)
    throw ValidationError(name +
                          ": the surface is non-orientable (like a Moebius strip or a Klein bottle): no choice "
                          "of face orientations agrees across every edge, so it has no UV map as one piece;" +
                          (repair ? std::string(" cut auto cuts it where they disagree (akvf param --cut auto)")
                                  : std::string(" repair auto with cut auto cuts it where they disagree (akvf param "
                                                "--repair auto --cut auto)")));
  if (!topology.misoriented_edge.empty())
    throw ValidationError(name + ": faces " + face_at_input(topology.misoriented_edge[2]) + " and " +
                          face_at_input(topology.misoriented_edge[3]) + " traverse edge (" +
                          at_input(topology.misoriented_edge[0]) + ", " + at_input(topology.misoriented_edge[1]) +
                          ") in the same direction" + numbering_note(b) + "; faces must be consistently oriented");

  // A vertex where two boundary fans meet starts two boundary half-edges.
  std::vector<char> starts_boundary(m.num_vertices(), 0);
  for (const auto& [from, to] : topology.boundary_half_edges)
    if (starts_boundary[from]++)
      throw ValidationError(name + ": vertex " + at_input(from) + numbering_note(b) +
                            " is non-manifold: two separate boundary fans meet there");
  if (cut) cut_into_charts(name, &out);
  find_chart_boundaries(name, &out);
  out.removed_corners = corner_sources(input, out.removed_faces, out.input_vertex);
  return out;
}

std::string cut_description(const DiskMesh& disk) {
  const int charts = disk.num_charts();
  std::string text = "cut into " + std::to_string(charts) + (charts == 1 ? " chart" : " charts") + " along " +
                     std::to_string(disk.cut_edges) + (disk.cut_edges == 1 ? " edge (" : " edges (");
  constexpr int kListed = 5;
  for (int c = 0; c < std::min(charts, kListed); ++c) {
    const int loops = disk.chart_input_loops[c];
    if (c > 0) text += "; ";
    if (charts > 1) text += "chart " + std::to_string(c) + ": ";
    text += "genus " + std::to_string(disk.chart_genus[c]) + ", " +
            (loops == 0 ? std::string("no boundary")
                        : std::to_string(loops) + (loops == 1 ? " boundary loop" : " boundary loops"));
  }
  if (charts > kListed) text += "; ...";
  return text + ")";
}

}  // namespace akvf
