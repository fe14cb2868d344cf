// --cut seams: paths from the peaks of the distortion to the boundary, the
// charts opened along them (still disks), and the distortion bound.
#include <doctest/doctest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>

#include "akvf/mesh_io.h"
#include "akvf/parameterize.h"
#include "framework/mesh/initialization.h"
#include "framework/mesh/mesh_topology.h"
#include "framework/mesh/mesh_validation.h"
#include "framework/mesh/overlap_free_pieces.h"
#include "framework/mesh/seam_opening.h"
#include "framework/mesh/uv_overlap.h"
#include "tests/cli_support.h"
#include "tests/test_support.h"

using akvf::TriMesh;

namespace {

// The grid's vertex at column i, row j (grid_disk numbers rows of nx).
int grid_vertex(int nx, int i, int j) { return j * nx + i; }

int euler_characteristic(const TriMesh& mesh) {
  return mesh.num_vertices() - akvf::edge_topology(mesh.F).num_edges + mesh.num_faces();
}

// The same energy at every vertex.
std::vector<double> flat(const TriMesh& mesh) { return std::vector<double>(mesh.num_vertices(), 4.0); }

}  // namespace

TEST_CASE("a seam from a boundary vertex takes the edge to its most distorted neighbour and leaves a disk") {
  const int n = 9;
  akvf::DiskMesh disk = akvf::prepare_disk_mesh(akvf::test::grid_disk(n, n), "grid", true);
  const int start = grid_vertex(n, 4, 0), inward = grid_vertex(n, 4, 1);
  std::vector<double> energy = flat(disk.mesh);
  energy[inward] = 5;
  energy[grid_vertex(n, 3, 0)] = energy[grid_vertex(n, 5, 0)] = 6;  // on the boundary: not cut toward
  const auto paths = akvf::seam_paths(disk.mesh, {start}, energy);
  REQUIRE(paths.size() == 1);
  CHECK(paths[0] == std::vector<int>{inward, start});
  const int vertices = disk.mesh.num_vertices();
  akvf::open_seams(&disk, paths);
  CHECK(disk.mesh.num_vertices() == vertices + 1);  // the start splits in two; the inner end is the tip
  CHECK(euler_characteristic(disk.mesh) == 1);
  CHECK(disk.boundary_loops.size() == 1);
}

TEST_CASE("a seam from a boundary vertex goes on along a crease while the vertices there are above the bound") {
  // The grid folded up by a right angle along its middle column: the
  // column's edges are a crease. Its vertices are distorted (5); a
  // neighbour off the crease more so (5.5), but the walk keeps to the crease.
  const int n = 9;
  TriMesh folded = akvf::test::grid_disk(n, n);
  for (int v = 0; v < folded.num_vertices(); ++v)
    if (const double x = folded.V(v, 0); x > 0.5) folded.V.row(v) << 0.5, folded.V(v, 1), x - 0.5;
  akvf::DiskMesh disk = akvf::prepare_disk_mesh(folded, "folded grid", true);
  std::vector<double> energy = flat(disk.mesh);
  for (int j = 1; j < n - 1; ++j) energy[grid_vertex(n, 4, j)] = 5;
  energy[grid_vertex(n, 3, 3)] = 5.5;
  const int start = grid_vertex(n, 4, 0);
  CHECK(akvf::seam_paths(disk.mesh, {start}, energy)[0].size() == 2);  // without a bound to walk above
  const auto paths = akvf::seam_paths(disk.mesh, {start}, energy, 4.2);
  REQUIRE(paths.size() == 1);
  std::vector<int> crease;
  for (int j = n - 2; j >= 0; --j) crease.push_back(grid_vertex(n, 4, j));
  CHECK(paths[0] == crease);  // to the last vertex before the far side
  akvf::open_seams(&disk, paths);
  CHECK(euler_characteristic(disk.mesh) == 1);
  CHECK(disk.boundary_loops.size() == 1);
}

TEST_CASE("a seam runs from an interior vertex to the boundary and opens the disk into a disk") {
  const int n = 9;
  akvf::DiskMesh disk = akvf::prepare_disk_mesh(akvf::test::grid_disk(n, n), "grid", true);
  const TriMesh before = disk.mesh;
  const int center = grid_vertex(n, 4, 4);
  const auto paths = akvf::seam_paths(disk.mesh, {center}, flat(disk.mesh));
  REQUIRE(paths.size() == 1);
  const std::vector<int>& path = paths[0];
  CHECK(path.front() == center);
  CHECK(path.size() == 5);  // four edges to the nearest side
  double length = 0;
  for (std::size_t i = 0; i + 1 < path.size(); ++i)
    length += (before.V.row(path[i]) - before.V.row(path[i + 1])).norm();

  const std::vector<int> source = akvf::open_seams(&disk, paths);
  // Every path vertex but the tip is split in two.
  CHECK(disk.mesh.num_vertices() == before.num_vertices() + 4);
  CHECK(static_cast<int>(source.size()) == disk.mesh.num_vertices());
  CHECK(euler_characteristic(disk.mesh) == 1);
  REQUIRE(disk.boundary_loops.size() == 1);
  CHECK(disk.boundary_loops[0].size() == 4 * (n - 1) + 8);  // the old loop and both sides of the seam
  CHECK(disk.cut_edges == 4);
  CHECK(disk.cut_length == doctest::Approx(length));
  for (int f = 0; f < before.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      CHECK(source[disk.mesh.F(f, k)] == before.F(f, k));
      CHECK(disk.input_vertex[disk.mesh.F(f, k)] == before.F(f, k));
    }
}

TEST_CASE("a later seam ends where it meets an earlier one, so the seams form trees") {
  const int n = 9;
  akvf::DiskMesh disk = akvf::prepare_disk_mesh(akvf::test::grid_disk(n, n), "grid", true);
  const auto first = akvf::seam_paths(disk.mesh, {grid_vertex(n, 4, 4)}, flat(disk.mesh));
  REQUIRE(first.size() == 1);
  // A vertex beside the first path's second vertex, farther from every side.
  const int beside =
      grid_vertex(n, first[0][1] % n == 4 ? 5 : first[0][1] % n, first[0][1] / n == 4 ? 5 : first[0][1] / n);
  const auto paths = akvf::seam_paths(disk.mesh, {grid_vertex(n, 4, 4), beside, grid_vertex(n, 4, 4)}, flat(disk.mesh));
  REQUIRE(paths.size() == 2);  // the repeated start lies on a path already
  const std::vector<int>& second = paths[1];
  CHECK(std::find(paths[0].begin(), paths[0].end(), second.back()) != paths[0].end());
  akvf::open_seams(&disk, paths);
  CHECK(euler_characteristic(disk.mesh) == 1);
  CHECK(disk.boundary_loops.size() == 1);
}

TEST_CASE("--cut seams bounds every chart's symmetric Dirichlet energy, flip-free and without overlap") {
  struct Case {
    const char* name;
    TriMesh mesh;
  };
  using namespace akvf::test;
  for (const Case& c : {Case{"sphere", sphere(3)}, Case{"torus", torus(12)},
                        Case{"annulus and sphere", side_by_side(annulus(), sphere(2), 6)}}) {
    const std::string name = c.name;
    CAPTURE(name);
    akvf::ParameterizeOptions options;
    options.cut = akvf::Cut::kAuto;
    const double cut_only = akvf::parameterize(c.mesh.V, c.mesh.F, options).distortion_energy;
    options.cut = akvf::Cut::kSeams;
    const akvf::ParameterizeResult r = akvf::parameterize(c.mesh.V, c.mesh.F, options);
    CAPTURE(r.message);
    CHECK(akvf::is_normal_termination(r.status));
    CHECK(r.distortion_bounded);
    CHECK(r.seam_stop_reason.empty());
    REQUIRE_FALSE(r.chart_distortion.empty());
    for (double e : r.chart_distortion) CHECK(e <= options.max_distortion);
    for (const auto& row : r.trace) CHECK(row.flips == 0);
    REQUIRE(r.uv_faces.rows() == c.mesh.num_faces());
    CHECK(r.uv_faces.maxCoeff() < r.uv.rows());
    CHECK(akvf::count_inverted_triangles(r.uv_faces, r.uv) == 0);
    CHECK(akvf::measure_uv_overlap(r.uv, r.uv_faces, std::vector<int>(r.uv_faces.rows(), 0)).overlapped_samples == 0);
    CHECK(r.seam_length > 0);
    if (cut_only > options.max_distortion) CHECK(r.seams_added > 0);
  }
}

TEST_CASE("a smooth sphere gets a few seams in one chart, not one-edge seams along its boundary") {
  // Were the peaks sought among interior vertices only, the vertex beside
  // each distorted boundary vertex would start a one-edge seam every round:
  // 88 seams in 2 charts on this sphere (docs/notes/2026-11-28-seam-peaks-and-switch-trials.md).
  const TriMesh mesh = akvf::test::sphere(5);
  akvf::ParameterizeOptions options;
  options.cut = akvf::Cut::kSeams;
  const akvf::ParameterizeResult r = akvf::parameterize(mesh.V, mesh.F, options);
  CAPTURE(r.message);
  CHECK(r.distortion_bounded);
  CHECK(r.chart_distortion.size() == 1);
  CHECK(r.seams_added <= 20);
}

TEST_CASE("a wavy sphere's seams start at its crests, not only at the tips of the seams before") {
  // A seam's tip is a peak of the distortion that grows as the mesh is
  // refined; measured against the tips, the crests would wait while the tips
  // grow one edge a round: 94 seams here with the tips as the measure
  // (docs/notes/2026-11-28-seam-tips-and-interior-peaks.md).
  TriMesh mesh = akvf::test::sphere(5);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    const Eigen::Vector3d p = mesh.V.row(v);
    mesh.V.row(v) *= 1 + 0.3 * std::sin(5 * p.x() + 2 * p.y()) * std::cos(4 * p.z());
  }
  akvf::ParameterizeOptions options;
  options.cut = akvf::Cut::kSeams;
  const akvf::ParameterizeResult r = akvf::parameterize(mesh.V, mesh.F, options);
  CAPTURE(r.message);
  CHECK(r.distortion_bounded);
  CHECK(r.seams_added <= 30);
}

TEST_CASE("a bound no seam can reach stops with the reason, the map still flip-free") {
  const TriMesh sphere = akvf::test::sphere(2);
  akvf::ParameterizeOptions options;
  options.cut = akvf::Cut::kSeams;
  options.max_distortion = 4 + 1e-12;
  const akvf::ParameterizeResult r = akvf::parameterize(sphere.V, sphere.F, options);
  CHECK(akvf::is_normal_termination(r.status));
  CHECK_FALSE(r.distortion_bounded);
  CHECK_FALSE(r.seam_stop_reason.empty());
  CHECK(akvf::count_inverted_triangles(r.uv_faces, r.uv) == 0);
}

TEST_CASE("param --cut seams reports the seams on stdout and in the summary") {
  namespace fs = std::filesystem;
  const fs::path dir = akvf::test::scratch_dir("cut_seams");
  akvf::test::write_obj(dir / "sphere.obj", akvf::test::sphere(3));
  const auto r = akvf::test::run_cli({"param", (dir / "sphere.obj").string(), "--cut", "seams", "--summary",
                                      (dir / "run.json").string(), "--out", (dir / "uv.obj").string(), "--quiet"});
  CHECK(r.code == 0);
  CHECK(r.out.find("sqrt(area) of seams in all; symmetric Dirichlet at most 4.2") != std::string::npos);
  std::ifstream in(dir / "run.json");
  const nlohmann::json summary = nlohmann::json::parse(in);
  CHECK(summary["seams"]["bound_met"] == true);
  CHECK(summary["seams"]["max_distortion"] == 4.2);
  CHECK(summary["settings"]["cut"] == "seams");

  const auto bad = akvf::test::run_cli(
      {"param", (dir / "sphere.obj").string(), "--cut", "seams", "--max-distortion", "3.5", "--quiet"});
  CHECK(bad.code != 0);
  CHECK(bad.err.find("--max-distortion") != std::string::npos);
}

TEST_CASE("uv_of refuses an x of another mesh's size, as a later round's of --cut seams") {
  const TriMesh sphere = akvf::test::sphere(2);
  akvf::ParameterizeOptions options;
  options.cut = akvf::Cut::kSeams;
  const akvf::Parameterizer solver(sphere.V, sphere.F, options);
  const std::string message = akvf::test::error_message([&] { solver.uv_of(Eigen::VectorXd::Zero(3)); });
  CHECK(message.find("Parameterizer::uv_of: x has 3 values") == 0);
}

TEST_CASE("a chart whose map winds over itself is cut into disks that do not overlap, the map kept") {
  // A strip of 40 by 2 cells wound one and a half times around a circle,
  // flip-free, and beside it a square that does not overlap itself.
  const int nx = 41, ny = 3;
  const TriMesh strip = akvf::test::grid_disk(nx, ny);
  const TriMesh square = akvf::test::grid_disk(3, 3);
  Eigen::MatrixXi F(strip.num_faces() + square.num_faces(), 3);
  F << square.F, strip.F.array() + square.num_vertices();
  Eigen::MatrixXd UV(square.num_vertices() + strip.num_vertices(), 2);
  UV.topRows(square.num_vertices()) = square.V.leftCols(2).array() + 5;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double angle = 3 * M_PI * i / (nx - 1), radius = 1.3 - 0.3 * j / (ny - 1);
      UV.row(square.num_vertices() + j * nx + i) << radius * std::cos(angle), radius * std::sin(angle);
    }
  std::vector<int> face_chart(F.rows(), 1);
  std::fill(face_chart.begin(), face_chart.begin() + square.num_faces(), 0);
  REQUIRE(akvf::measure_uv_overlap(UV, F, face_chart).overlapped_samples > 0);

  std::vector<int> pieces;
  const int count = akvf::overlap_free_pieces(F, UV, face_chart, 2, &pieces);
  CHECK(count == 3);  // the square whole, the strip in two
  for (int f = 0; f < square.num_faces(); ++f) CHECK(pieces[f] == 0);
  CHECK(akvf::measure_uv_overlap(UV, F, pieces).overlapped_samples == 0);
  for (int p = 1; p < count; ++p) {
    std::vector<int> rows;
    for (int f = 0; f < F.rows(); ++f)
      if (pieces[f] == p) rows.push_back(f);
    Eigen::MatrixXi piece(rows.size(), 3);
    for (std::size_t r = 0; r < rows.size(); ++r) piece.row(r) = F.row(rows[r]);
    std::set<int> vertices(piece.data(), piece.data() + piece.size());
    CHECK(akvf::count_components(piece, UV.rows()) == 1);
    CHECK(static_cast<int>(vertices.size()) - akvf::edge_topology(piece).num_edges + piece.rows() == 1);
  }
}

TEST_CASE("a CAD-like cylinder ends in one chart: seams along its rims, the flip-free map kept if need be") {
  // Caps of 64 sides and one row of quads ten times as tall as the radius,
  // as a CAD export writes them: the caps as polygons (the reader
  // triangulates them) or as fans. Seams grown one edge a round along the
  // rims ended in 54 and 55 charts. With fans the flip-free rounds
  // meet the bound with seams whose sides touch, which the barrier then
  // holds apart, the energy above the bound; the flip-free map, whose
  // boundary crosses itself nowhere, is kept
  // (docs/notes/2026-11-28-touching-seams-and-even-cuts.md).
  const int n = 64;
  std::ostringstream polygons, fans;
  for (int level = 0; level < 2; ++level)
    for (int i = 0; i < n; ++i) {
      const double x = std::cos(2 * M_PI * i / n), y = std::sin(2 * M_PI * i / n);
      polygons << "v " << x << " " << y << " " << 10 * level << "\n";
      fans << "v " << x << " " << y << " " << 10 * level << "\n";
    }
  polygons << "f";
  for (int i = n; i >= 1; --i) polygons << " " << i;
  polygons << "\nf";
  for (int i = n + 1; i <= 2 * n; ++i) polygons << " " << i;
  polygons << "\n";
  for (int i = 2; i < n; ++i)
    fans << "f 1 " << i + 1 << " " << i << "\nf " << n + 1 << " " << n + i << " " << n + i + 1 << "\n";
  for (int i = 0; i < n; ++i) {
    const std::string side = "f " + std::to_string(i + 1) + " " + std::to_string((i + 1) % n + 1) + " " +
                             std::to_string(n + (i + 1) % n + 1) + " " + std::to_string(n + i + 1) + "\n";
    polygons << side;
    fans << side;
  }
  for (const auto& cylinder_obj :
       {std::pair{std::string("polygons"), polygons.str()}, std::pair{std::string("fans"), fans.str()}}) {
    const std::string& caps = cylinder_obj.first;
    CAPTURE(caps);
    std::istringstream in(cylinder_obj.second);
    akvf::Warnings warnings;
    const TriMesh cylinder = akvf::read_obj(in, "cylinder.obj", &warnings);
    akvf::ParameterizeOptions options;
    options.cut = akvf::Cut::kSeams;
    const akvf::ParameterizeResult r = akvf::parameterize(cylinder.V, cylinder.F, options);
    CAPTURE(r.message);
    CHECK(akvf::is_normal_termination(r.status));
    CHECK(r.distortion_bounded);
    CHECK(r.chart_distortion.size() == 1);
    CHECK(r.boundary_crossings == 0);
    CHECK(r.overlap_fraction == 0);
    CHECK(akvf::count_inverted_triangles(r.uv_faces, r.uv) == 0);
    // The trace ends at the map returned (without the barrier: either the
    // barrier was nowhere near, or the kept map is flip-free only).
    REQUIRE_FALSE(r.trace.empty());
    CHECK(r.trace.back().energy == doctest::Approx(r.distortion_energy).epsilon(1e-9));
  }
}

TEST_CASE("--cut seams on a sphere with spikes: the bound in every chart, no overlap, by seams or by pieces") {
  // Every 53rd vertex of a subdivided octahedron, or every 5th of a coarser
  // one, pushed out to three times the radius: thin cones whose flip-free
  // maps wind over each other.
  for (const std::pair<int, int>& spikes : {std::pair{4, 53}, std::pair{3, 5}}) {
    const int rounds = spikes.first, every = spikes.second;
    CAPTURE(every);
    TriMesh spiky = akvf::test::sphere(rounds);
    for (int v = every / 3; v < spiky.num_vertices(); v += every) spiky.V.row(v) *= 3;
    akvf::ParameterizeOptions options;
    options.cut = akvf::Cut::kSeams;
    options.min_coverage = 0;  // the seams alone; the cuts for the packing are tested on their own
    const akvf::ParameterizeResult r = akvf::parameterize(spiky.V, spiky.F, options);
    CAPTURE(r.message);
    CHECK(akvf::is_normal_termination(r.status));
    CHECK(r.distortion_bounded);
    CHECK(r.boundary_crossings == 0);
    CHECK(r.overlap_fraction == 0);
    CHECK(akvf::count_inverted_triangles(r.uv_faces, r.uv) == 0);
    for (double e : r.chart_distortion) CHECK(e <= options.max_distortion);
    CHECK(r.seam_stop_reason.empty());
    if (every == 5) CHECK(r.parted_charts > 0);  // seams and pieces alone leave a chart above the bound
  }
}
