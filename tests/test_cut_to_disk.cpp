// --cut auto: closed, multi-boundary, higher-genus and multi-component meshes
// cut into one disk per component, parameterized flip-free, charts side by
// side, written with per-corner vt.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <fstream>
#include <numeric>
#include <sstream>

#include "akvf/parameterize.h"
#include "framework/mesh/chart_layout.h"
#include "framework/mesh/chart_splitting.h"
#include "framework/mesh/cut_to_disk.h"
#include "framework/mesh/initialization.h"
#include "framework/mesh/mesh_topology.h"
#include "framework/mesh/mesh_validation.h"
#include "framework/mesh/seam_opening.h"
#include "framework/mesh/uv_overlap.h"
#include "tests/cli_support.h"
#include "tests/test_support.h"

using akvf::TriMesh;

namespace {

struct Case {
  const char* name;
  TriMesh mesh;
  int charts, genus, loops;  // genus and loops of the first chart
};

std::vector<Case> cases() {
  using namespace akvf::test;
  TriMesh tetrahedron;
  tetrahedron.V.resize(4, 3);
  tetrahedron.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  tetrahedron.F.resize(4, 3);
  tetrahedron.F << 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2;
  return {
      {"sphere", sphere(2), 1, 0, 0},    {"tetrahedron (the far end is the root's neighbour)", tetrahedron, 1, 0, 0},
      {"torus", torus(12), 1, 1, 0},     {"punctured torus", torus(8, 1), 1, 1, 1},
      {"annulus", annulus(), 1, 0, 2},   {"annulus and torus", side_by_side(annulus(), torus(8), 6), 2, 0, 2},
      {"disk", grid_disk(5, 5), 1, 0, 1}};
}

// Whether any two triangles of the map overlap (charts included), sampled.
bool any_overlap(const Eigen::MatrixXd& uv, const Eigen::MatrixXi& faces) {
  return akvf::measure_uv_overlap(uv, faces, std::vector<int>(faces.rows(), 0)).overlapped_samples > 0;
}

}  // namespace

TEST_CASE("the automatic cut leaves one disk per component and keeps the faces") {
  for (const Case& c : cases()) {
    CAPTURE(c.name);
    const akvf::DiskMesh disk = akvf::prepare_disk_mesh(c.mesh, c.name, true);  // throws unless every chart is a disk
    CHECK(disk.num_charts() == c.charts);
    CHECK(disk.chart_genus[0] == c.genus);
    CHECK(disk.chart_input_loops[0] == c.loops);
    REQUIRE(disk.mesh.num_faces() == c.mesh.num_faces());
    for (int f = 0; f < c.mesh.num_faces(); ++f)
      for (int k = 0; k < 3; ++k) CHECK(disk.input_vertex[disk.mesh.F(f, k)] == c.mesh.F(f, k));
    // Every seam edge is opened once: two more vertices per interior cut
    // edge, less one per path end, is not needed here; the disk check holds.
    const int euler = disk.mesh.num_vertices() - akvf::edge_topology(disk.mesh.F).num_edges + disk.mesh.num_faces();
    CHECK(euler == c.charts);
  }
}

TEST_CASE("a disk is not cut") {
  const TriMesh grid = akvf::test::grid_disk(6, 4);
  const akvf::DiskCut cut = akvf::cut_to_disks(grid);
  CHECK(cut.cut_edges == 0);
  CHECK(cut.mesh.F == grid.F);
  CHECK(cut.mesh.V == grid.V);
}

TEST_CASE("a torus is cut along two loops of a shortest-path tree") {
  const akvf::DiskCut cut = akvf::cut_to_disks(akvf::test::torus(12));
  // Two non-contractible loops through one vertex: at least the tube's and
  // the ring's circumferences in edges (12 each), and far from every edge.
  CHECK(cut.cut_edges >= 24);
  CHECK(cut.cut_edges < 60);
}

TEST_CASE("the cut refuses a vertex where two closed fans meet") {
  // Two tetrahedron surfaces sharing vertex 0.
  TriMesh m;
  m.V.resize(7, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1, -1, 0, 0, 0, -1, 0, 0, 0, -1;
  m.F.resize(8, 3);
  m.F << 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2, 0, 5, 4, 0, 4, 6, 4, 5, 6, 0, 6, 5;
  const std::string message = akvf::test::error_message([&] { akvf::prepare_disk_mesh(m, "pinch.obj", true); });
  CHECK(message ==
        "pinch.obj: vertex 0 (numbered from 0) is non-manifold: its faces form separate fans that meet there");
}

TEST_CASE("cut meshes parameterize flip-free at every iterate, charts side by side") {
  for (const Case& c : cases()) {
    CAPTURE(c.name);
    akvf::ParameterizeOptions options;
    options.cut = akvf::Cut::kAuto;
    options.init = akvf::InitialMap::kTutte;  // some are developable: their conformal map is the minimum
    options.max_iters = 300;
    const akvf::ParameterizeResult r = akvf::parameterize(c.mesh.V, c.mesh.F, options);
    CHECK(akvf::is_normal_termination(r.status));
    for (const auto& row : r.trace) CHECK(row.flips == 0);
    CHECK(r.energy() < r.trace.front().energy);
    REQUIRE(r.uv_faces.rows() == c.mesh.num_faces());
    CHECK(r.uv_faces.maxCoeff() < r.uv.rows());
    CHECK(akvf::count_inverted_triangles(r.uv_faces, r.uv) == 0);
    CHECK_FALSE(any_overlap(r.uv, r.uv_faces));
  }
}

TEST_CASE("output packing turns charts flat, never mirrors them, keeps them apart and fills the square better") {
  // 24 thin rectangles (2 triangles each) at random angles and lengths.
  const int n = 24;
  Eigen::MatrixXi F(2 * n, 3);
  Eigen::MatrixXd UV(4 * n, 2);
  std::vector<int> face_chart(2 * n);
  for (int c = 0; c < n; ++c) {
    const double length = 1 + c % 5, angle = 0.37 * c;
    const Eigen::Matrix2d R = Eigen::Rotation2Dd(angle).toRotationMatrix();
    const Eigen::Vector2d corners[4] = {{0, 0}, {length, 0}, {length, 0.3}, {0, 0.3}};
    for (int k = 0; k < 4; ++k) UV.row(4 * c + k) = (R * corners[k]).transpose() + Eigen::RowVector2d(7.0 * c, 0);
    F.row(2 * c) << 4 * c, 4 * c + 1, 4 * c + 2;
    F.row(2 * c + 1) << 4 * c, 4 * c + 2, 4 * c + 3;
    face_chart[2 * c] = face_chart[2 * c + 1] = c;
  }
  Eigen::MatrixXd plain = UV, tight = UV;
  akvf::pack_charts(F, face_chart, n, &plain);
  akvf::pack_charts(F, face_chart, n, &tight, true);
  CHECK(akvf::square_coverage(F, tight) > 1.5 * akvf::square_coverage(F, plain));
  CHECK(akvf::square_coverage(F, tight) > 0.5);
  for (int c = 0; c < n; ++c) {
    CAPTURE(c);
    // A rigid motion: every distance kept, the orientation too.
    for (int a = 0; a < 4; ++a)
      for (int b = a + 1; b < 4; ++b)
        CHECK((tight.row(4 * c + a) - tight.row(4 * c + b)).norm() ==
              doctest::Approx((UV.row(4 * c + a) - UV.row(4 * c + b)).norm()).epsilon(1e-12));
    CHECK(akvf::count_inverted_triangles(F.middleRows(2 * c, 2), tight) == 0);
    // Flat or turned a quarter: the rectangle lies along u or v.
    const Eigen::RowVector2d side = tight.row(4 * c + 1) - tight.row(4 * c);
    CHECK(std::min(std::abs(side.x()), std::abs(side.y())) < 1e-9);
  }
  CHECK_FALSE(any_overlap(plain, F));
  CHECK_FALSE(any_overlap(tight, F));
  Eigen::MatrixXi doubled(4, 3);
  doubled << F.topRows(2), F.topRows(2);
  CHECK(any_overlap(tight, doubled));  // the check sees an overlap
}

TEST_CASE("one chart turns to its smallest bounding square") {
  // A 5 x 0.3 rectangle at 0.4 rad: its smallest square stands on a corner,
  // side (5 + 0.3) / sqrt(2), where lying flat it needs 5.
  Eigen::MatrixXi F(2, 3);
  F << 0, 1, 2, 0, 2, 3;
  Eigen::MatrixXd UV(4, 2);
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(0.4).toRotationMatrix();
  const Eigen::Vector2d corners[4] = {{0, 0}, {5, 0}, {5, 0.3}, {0, 0.3}};
  for (int k = 0; k < 4; ++k) UV.row(k) = (R * corners[k]).transpose();
  Eigen::MatrixXd kept = UV, turned = UV;
  akvf::pack_charts(F, {0, 0}, 1, &kept);
  CHECK(kept == UV);  // without rotate_to_boxes one chart stays as it is
  akvf::pack_charts(F, {0, 0}, 1, &turned, true);
  const double side = 5.3 / std::sqrt(2.0);
  CHECK(akvf::square_coverage(F, turned) == doctest::Approx(1.5 / (side * side)).epsilon(1e-9));
  CHECK(akvf::count_inverted_triangles(F, turned) == 0);
  CHECK((turned.row(1) - turned.row(0)).norm() == doctest::Approx(5).epsilon(1e-12));
}

// The least distance between two segments of the plane that do not cross.
double segment_distance(Eigen::RowVector2d a, Eigen::RowVector2d b, Eigen::RowVector2d c, Eigen::RowVector2d d) {
  const auto to_segment = [](Eigen::RowVector2d p, Eigen::RowVector2d s, Eigen::RowVector2d t) {
    const Eigen::RowVector2d e = t - s;
    const double u = std::clamp((p - s).dot(e) / e.squaredNorm(), 0.0, 1.0);
    return (p - s - u * e).norm();
  };
  return std::min({to_segment(a, c, d), to_segment(b, c, d), to_segment(c, a, b), to_segment(d, a, b)});
}

TEST_CASE("a gutter keeps packed charts that share of the square apart, in rows and interlocked") {
  // Charts of one shape (its outline, triangulated from its first corner),
  // n of them at several sizes and angles.
  struct Charts {
    Eigen::MatrixXi F;
    Eigen::MatrixXd UV;
    std::vector<int> face_chart;
    int corners = 0;
  };
  const auto charts = [](const std::vector<Eigen::Vector2d>& outline, int n) {
    Charts out;
    const int k = static_cast<int>(outline.size());
    out.corners = k;
    out.F.resize(n * (k - 2), 3);
    out.UV.resize(n * k, 2);
    for (int c = 0; c < n; ++c) {
      const Eigen::Matrix2d R = (1 + c % 5) * Eigen::Rotation2Dd(0.37 * c).toRotationMatrix();
      for (int i = 0; i < k; ++i)
        out.UV.row(k * c + i) = (R * outline[i]).transpose() + Eigen::RowVector2d(20.0 * c, 0);
      for (int i = 1; i + 1 < k; ++i) {
        out.F.row(c * (k - 2) + i - 1) << k * c, k * c + i, k * c + i + 1;
        out.face_chart.push_back(c);
      }
    }
    return out;
  };
  // The least distance between two charts' outlines, over the square's side.
  const auto least_gap = [](const Charts& set, const Eigen::MatrixXd& packed) {
    const double side = (packed.colwise().maxCoeff() - packed.colwise().minCoeff()).maxCoeff();
    const int k = set.corners, n = static_cast<int>(packed.rows()) / k;
    double least = std::numeric_limits<double>::infinity();
    for (int c = 0; c < n; ++c)
      for (int d = c + 1; d < n; ++d)
        for (int i = 0; i < k; ++i)
          for (int j = 0; j < k; ++j)
            least = std::min(least, segment_distance(packed.row(k * c + i), packed.row(k * c + (i + 1) % k),
                                                     packed.row(k * d + j), packed.row(k * d + (j + 1) % k)));
    return least / side;
  };
  // Rectangles (rows of boxes suit them) and L shapes (the grid interlocks
  // them: its layout covers more of the square than the rows').
  const Charts rectangles = charts({{0, 0}, {1, 0}, {1, 0.3}, {0, 0.3}}, 24);
  const Charts ells = charts({{0.5, 0.5}, {0.5, 2}, {0, 2}, {0, 0}, {2, 0}, {2, 0.5}}, 40);
  for (const Charts* set : {&rectangles, &ells}) {
    const int n = set->F.rows() / (set->corners - 2);
    for (const double gutter : {0.0, 0.01, 0.03, 0.06}) {
      CAPTURE(set->corners);
      CAPTURE(gutter);
      Eigen::MatrixXd packed = set->UV;
      akvf::pack_charts(set->F, set->face_chart, n, &packed, true, gutter);
      if (gutter > 0) CHECK(least_gap(*set, packed) / gutter >= 1 - 1e-9);
      if (gutter == 0) CHECK(least_gap(*set, packed) < 0.03);  // the check can fail: charts lie closer
      CHECK_FALSE(any_overlap(packed, set->F));
    }
  }
  Eigen::MatrixXd rows = ells.UV, interlocked = ells.UV;
  akvf::pack_charts(ells.F, ells.face_chart, 40, &rows);
  akvf::pack_charts(ells.F, ells.face_chart, 40, &interlocked, true, 0.01);
  CHECK(akvf::square_coverage(ells.F, interlocked) > 1.3 * akvf::square_coverage(ells.F, rows));
}

TEST_CASE("thin wedges interlock by half turns") {
  // 60 single-triangle charts, each a wedge 0.25 wide and 2 long: their
  // boxes are twice their area, so rows cover at most half the square, as
  // do the grid's layouts with quarter turns alone (45 %); two wedges, one
  // turned by half a turn, fill a parallelogram.
  const int n = 60;
  Eigen::MatrixXi F(n, 3);
  Eigen::MatrixXd UV(3 * n, 2);
  std::vector<int> face_chart(n);
  for (int c = 0; c < n; ++c) {
    UV.row(3 * c) << 3.0 * c, 0;
    UV.row(3 * c + 1) << 3.0 * c + 0.25, 0;
    UV.row(3 * c + 2) << 3.0 * c + 0.125, 2;
    F.row(c) << 3 * c, 3 * c + 1, 3 * c + 2;
    face_chart[c] = c;
  }
  akvf::pack_charts(F, face_chart, n, &UV, true, 2.0 / 1024);
  CHECK_FALSE(any_overlap(UV, F));
  CHECK(akvf::square_coverage(F, UV) > 0.52);
}

TEST_CASE("below the coverage asked, thin sectors also take eighth turns") {
  // 64 charts, each a sector of 0.3 radians of a disk of radius 2 (a fan
  // of four triangles): with quarter turns they cover 58 % of the square,
  // fanned by eighth turns (as a cone's unrolled spikes) 67 %.
  const int n = 64, fan = 4;
  Eigen::MatrixXi F(fan * n, 3);
  Eigen::MatrixXd UV((fan + 2) * n, 2);
  std::vector<int> face_chart(fan * n);
  for (int c = 0; c < n; ++c) {
    const int apex = (fan + 2) * c;
    UV.row(apex) << 5.0 * c, 0;
    for (int k = 0; k <= fan; ++k) {
      const double angle = 0.3 * k / fan;
      UV.row(apex + 1 + k) = UV.row(apex) + 2 * Eigen::RowVector2d(std::cos(angle), std::sin(angle));
    }
    for (int k = 0; k < fan; ++k) {
      F.row(fan * c + k) << apex, apex + 1 + k, apex + 2 + k;
      face_chart[fan * c + k] = c;
    }
  }
  Eigen::MatrixXd quarter = UV, eighth = UV;
  akvf::pack_charts(F, face_chart, n, &quarter, true, 2.0 / 1024);
  akvf::pack_charts(F, face_chart, n, &eighth, true, 2.0 / 1024, akvf::PackingGrid::kFine, 0.6);
  CHECK_FALSE(any_overlap(eighth, F));
  CHECK(akvf::square_coverage(F, eighth) > akvf::square_coverage(F, quarter) + 0.05);
  CHECK(akvf::square_coverage(F, eighth) > 0.65);
}

TEST_CASE("hundreds of small charts pack the gutter apart, not a share of the square") {
  // 400 squares of sides 1 to 1.5: in rows the gutter apart they cover
  // most of the square (with 2 % of its side between boxes, 59 %).
  const int n = 400;
  Eigen::MatrixXi F(2 * n, 3);
  Eigen::MatrixXd UV(4 * n, 2);
  std::vector<int> face_chart(2 * n);
  for (int c = 0; c < n; ++c) {
    const double side = 1 + 0.5 * (c % 7) / 6;
    const Eigen::RowVector2d corners[4] = {{0, 0}, {side, 0}, {side, side}, {0, side}};
    for (int k = 0; k < 4; ++k) UV.row(4 * c + k) = corners[k] + Eigen::RowVector2d(3.0 * c, 0);
    F.row(2 * c) << 4 * c, 4 * c + 1, 4 * c + 2;
    F.row(2 * c + 1) << 4 * c, 4 * c + 2, 4 * c + 3;
    face_chart[2 * c] = face_chart[2 * c + 1] = c;
  }
  const double gutter = 2.0 / 1024;  // the default: 2 texels of 1024
  akvf::pack_charts(F, face_chart, n, &UV, true, gutter);
  CHECK_FALSE(any_overlap(UV, F));
  CHECK(akvf::square_coverage(F, UV) > 0.75);
}

// A flat comb of unit squares: a base 1 high and `teeth` teeth 5 long.
TriMesh comb(int teeth) {
  const int width = 2 * teeth - 1, height = 6;
  TriMesh m;
  m.V.resize((width + 1) * (height + 1), 3);
  for (int y = 0; y <= height; ++y)
    for (int x = 0; x <= width; ++x) m.V.row(y * (width + 1) + x) << x, y, 0;
  std::vector<Eigen::Vector3i> faces;
  for (int y = 0; y < height; ++y)
    for (int x = 0; x < width; ++x) {
      if (y > 0 && x % 2 == 1) continue;  // between the teeth
      const int a = y * (width + 1) + x, b = a + 1, c = a + width + 1, d = c + 1;
      faces.push_back({a, b, d});
      faces.push_back({a, d, c});
    }
  m.F.resize(static_cast<Eigen::Index>(faces.size()), 3);
  for (std::size_t f = 0; f < faces.size(); ++f) m.F.row(f) = faces[f].transpose();
  return m;
}

TEST_CASE("straight cuts of a comb: least waste first, every piece a disk, opened along the edges between them") {
  const TriMesh m = comb(5);
  const Eigen::MatrixXd UV = m.V.leftCols(2);
  const std::vector<int> one(m.num_faces(), 0);
  const double whole = akvf::chart_waste(m.F, UV, one, 1)[0];
  const auto splits = akvf::straight_splits(m.F, UV, one, 1, 0, 4, [](const akvf::ChartSplit&) { return true; });
  REQUIRE(splits.size() == 4);
  for (std::size_t i = 0; i < splits.size(); ++i) {
    CAPTURE(i);
    const akvf::ChartSplit& s = splits[i];
    CHECK(s.num_charts >= 2);
    if (i > 0) CHECK(s.waste >= splits[i - 1].waste);
    const std::vector<double> waste = akvf::chart_waste(m.F, UV, s.face_chart, s.num_charts);
    CHECK(std::accumulate(waste.begin(), waste.end(), 0.0) == doctest::Approx(s.waste));
  }
  CHECK(splits[0].waste < 0.5 * whole);  // the teeth cut off: the pieces nearly convex
  CHECK(akvf::straight_splits(m.F, UV, one, 1, 0, 4, [](const akvf::ChartSplit&) { return false; }).empty());

  akvf::DiskMesh disk = akvf::prepare_disk_mesh(m, "comb", true);
  const int edges = disk.cut_edges;
  const std::vector<int> source = akvf::split_charts(&disk, splits[0].face_chart, splits[0].num_charts);
  CHECK(disk.num_charts() == splits[0].num_charts);
  CHECK(disk.face_chart == splits[0].face_chart);
  CHECK(disk.cut_edges > edges);
  REQUIRE(static_cast<int>(source.size()) == disk.mesh.num_vertices());
  for (const auto& loop : disk.boundary_loops) CHECK(loop.size() >= 3);
  // Charts share no vertex, and each vertex copies one of the same place.
  std::vector<int> chart_of(disk.mesh.num_vertices(), -1);
  for (int f = 0; f < disk.mesh.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) {
      int& c = chart_of[disk.mesh.F(f, k)];
      CHECK((c < 0 || c == disk.face_chart[f]));
      c = disk.face_chart[f];
    }
  for (int v = 0; v < disk.mesh.num_vertices(); ++v) CHECK(disk.mesh.V.row(v) == m.V.row(source[v]));
}

TEST_CASE("charts split for the packing: the map kept, the square better covered") {
  // Two combs: their teeth leave most of their squares empty.
  const TriMesh combs = akvf::test::side_by_side(comb(5), comb(4), 12);
  akvf::ParameterizeOptions options;
  options.cut = akvf::Cut::kAuto;
  options.min_coverage = 0;
  const akvf::ParameterizeResult whole = akvf::parameterize(combs.V, combs.F, options);
  options.min_coverage = 0.6;
  const akvf::ParameterizeResult split = akvf::parameterize(combs.V, combs.F, options);
  CHECK(whole.packing_splits == 0);
  CHECK(split.packing_splits > 0);
  const double before = akvf::square_coverage(whole.uv_faces, whole.uv);
  const double after = akvf::square_coverage(split.uv_faces, split.uv);
  CAPTURE(before);
  CAPTURE(after);
  CHECK(after > 1.01 * before);
  REQUIRE(split.uv_faces.rows() == combs.num_faces());
  CHECK(akvf::count_inverted_triangles(split.uv_faces, split.uv) == 0);
  CHECK_FALSE(any_overlap(split.uv, split.uv_faces));
  // Every triangle as it was: the same side lengths, up to the packing's
  // common scale.
  const auto side = [](const akvf::ParameterizeResult& r, int f, int k) {
    return (r.uv.row(r.uv_faces(f, (k + 1) % 3)) - r.uv.row(r.uv_faces(f, k))).norm();
  };
  const double scale = side(split, 0, 0) / side(whole, 0, 0);
  for (int f = 0; f < combs.num_faces(); ++f)
    for (int k = 0; k < 3; ++k) CHECK(side(split, f, k) == doctest::Approx(scale * side(whole, f, k)).epsilon(1e-9));
  CHECK(split.energy() == whole.energy());
}

TEST_CASE("two equal squares, convex so wasting no hull area, are cut through the middle for the packing") {
  // Side by side they fill half of the square, whatever their turns.
  const TriMesh squares = akvf::test::side_by_side(akvf::test::grid_disk(9, 9), akvf::test::grid_disk(9, 9), 12);
  const TriMesh square = akvf::test::grid_disk(9, 9);
  const Eigen::MatrixXd UV = square.V.leftCols(2);
  const std::vector<int> one(square.num_faces(), 0);
  const auto accept = [](const akvf::ChartSplit&) { return true; };
  const auto even = akvf::straight_splits(square.F, UV, one, 1, 0, 4, accept, akvf::SplitRank::kEvenPieces);
  REQUIRE(even.size() == 4);
  const std::vector<double> area = akvf::chart_areas(square.F, UV, even[0].face_chart, even[0].num_charts);
  REQUIRE(area.size() == 2);
  CHECK(area[0] == doctest::Approx(area[1]));  // halves
  for (std::size_t i = 1; i < even.size(); ++i) CHECK(even[i].rank >= even[i - 1].rank);
  // By waste alone every cut of a square ties at none, the first found first.
  const auto least = akvf::straight_splits(square.F, UV, one, 1, 0, 1, accept);
  CHECK(least[0].waste == doctest::Approx(0).epsilon(1e-12));
  akvf::ParameterizeOptions options;
  options.cut = akvf::Cut::kAuto;
  const akvf::ParameterizeResult r = akvf::parameterize(squares.V, squares.F, options);
  CHECK(r.packing_splits > 0);
  CHECK(akvf::square_coverage(r.uv_faces, r.uv) >= options.min_coverage);
  CHECK(akvf::count_inverted_triangles(r.uv_faces, r.uv) == 0);
  CHECK_FALSE(any_overlap(r.uv, r.uv_faces));
}

TEST_CASE("without the cut the default is unchanged: uv per vertex, uv_faces = F") {
  const TriMesh grid = akvf::test::bumpy_disk(8, 8);
  akvf::ParameterizeOptions options;
  const akvf::ParameterizeResult plain = akvf::parameterize(grid.V, grid.F, options);
  options.cut = akvf::Cut::kAuto;
  const akvf::ParameterizeResult cut = akvf::parameterize(grid.V, grid.F, options);
  CHECK(plain.uv_faces == grid.F);
  CHECK(cut.uv_faces == grid.F);  // a disk is not cut: same numbering
  CHECK(cut.uv == plain.uv);
  CHECK(cut.energy() == plain.energy());
}

TEST_CASE("param --cut auto writes the input's v and f with per-corner vt") {
  namespace fs = std::filesystem;
  const fs::path dir = akvf::test::scratch_dir("cut_auto");
  const TriMesh torus = akvf::test::torus(10);
  akvf::test::write_obj(dir / "torus.obj", torus);
  const auto refused = akvf::test::run_cli({"param", (dir / "torus.obj").string(), "--quiet"});
  CHECK(refused.code != 0);
  CHECK(refused.err.find("--cut auto") != std::string::npos);

  const auto r = akvf::test::run_cli(
      {"param", (dir / "torus.obj").string(), "--cut", "auto", "--out", (dir / "uv.obj").string(), "--quiet"});
  CHECK(r.code == 0);
  CHECK(r.out.find("cut into 1 chart along ") != std::string::npos);
  std::ifstream in(dir / "uv.obj");
  std::string line;
  std::vector<Eigen::RowVector2d> vt;
  int v = 0, f = 0, inverted = 0;
  while (std::getline(in, line)) {
    std::istringstream words(line);
    std::string tag;
    words >> tag;
    if (tag == "v") ++v;
    if (tag == "vt") {
      Eigen::RowVector2d t;
      words >> t[0] >> t[1];
      vt.push_back(t);
    }
    if (tag == "f") {
      ++f;
      Eigen::RowVector2d corner[3];
      for (int k = 0; k < 3; ++k) {
        std::string pair;
        words >> pair;
        const int p = std::stoi(pair.substr(0, pair.find('/'))), t = std::stoi(pair.substr(pair.find('/') + 1));
        CHECK(p == torus.F(f - 1, k) + 1);
        REQUIRE(t >= 1);
        REQUIRE(t <= static_cast<int>(vt.size()));
        corner[k] = vt[t - 1];
      }
      const Eigen::RowVector2d e1 = corner[1] - corner[0], e2 = corner[2] - corner[0];
      inverted += !(e1.x() * e2.y() - e1.y() * e2.x() > 0);
    }
  }
  CHECK(v == torus.num_vertices());
  CHECK(f == torus.num_faces());
  CHECK(static_cast<int>(vt.size()) > torus.num_vertices());  // seam vertices have one vt per side
  CHECK(inverted == 0);
  fs::remove_all(dir);
}
