// Disk-mesh validation: one test per way a mesh can be unfit, each checking
// its message.
#include <doctest/doctest.h>

#include <array>
#include <cmath>
#include <limits>

#include "akvf/parameterize.h"
#include "akvf/rest_geometry.h"
#include "framework/mesh/initialization.h"
#include "framework/mesh/mesh_subdivision.h"
#include "framework/mesh/mesh_validation.h"
#include "tests/test_support.h"

using akvf::TriMesh;
using akvf::test::error_message;

namespace {

std::string validation_error(const TriMesh& mesh) {
  return error_message([&] { akvf::prepare_disk_mesh(mesh, "m.obj"); });
}

// A closed tetrahedron surface.
TriMesh tetrahedron() {
  TriMesh m;
  m.V.resize(4, 3);
  m.V << 0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1;
  m.F.resize(4, 3);
  m.F << 0, 2, 1, 0, 1, 3, 1, 2, 3, 0, 3, 2;
  return m;
}

TriMesh annulus() { return akvf::test::annulus(); }
TriMesh punctured_torus() { return akvf::test::torus(6, 1); }

}  // namespace

TEST_CASE("a grid is a valid disk with its boundary loop") {
  const auto disk = akvf::prepare_disk_mesh(akvf::test::grid_disk(5, 4), "grid.obj");
  REQUIRE(disk.num_charts() == 1);
  CHECK(disk.boundary_loops[0].size() == 14);
  CHECK(disk.warnings.empty());
}

TEST_CASE("a closed mesh must be cut first") {
  CHECK(validation_error(tetrahedron()) ==
        "m.obj: mesh is closed (no boundary loop); it must be cut to a disk first: use the option cut auto (akvf param "
        "--cut auto)");
}

TEST_CASE("several boundary loops must be cut first") {
  CHECK(validation_error(annulus()) ==
        "m.obj: mesh has 2 boundary loops (a disk has exactly one); it must be cut to a disk first: use the option cut "
        "auto (akvf param --cut auto)");
}

TEST_CASE("a handle is reported by the Euler characteristic") {
  CHECK(validation_error(punctured_torus()) ==
        "m.obj: Euler characteristic is -1 (a disk has 1): the mesh has handles; it must be cut to a disk first: use "
        "the option cut auto (akvf param --cut auto)");
}

TEST_CASE("two components are rejected") {
  const TriMesh a = akvf::test::grid_disk(3, 3), two = akvf::test::side_by_side(a, a, 5);
  CHECK(validation_error(two) ==
        "m.obj: mesh has 2 connected components; parameterize one disk-shaped component at a time, or all as "
        "charts side by side with the option cut auto (akvf param --cut auto)");
}

TEST_CASE("an edge shared by three faces is non-manifold") {
  TriMesh m = akvf::test::grid_disk(3, 3);
  m.V.conservativeResize(m.num_vertices() + 1, 3);
  m.V.row(m.num_vertices() - 1) << 0.5, 0.5, 1;
  m.F.conservativeResize(m.num_faces() + 1, 3);
  m.F.row(m.num_faces() - 1) << 0, 4, m.num_vertices() - 1;  // edge (0, 4) is a diagonal of two faces
  CHECK(validation_error(m) ==
        "m.obj: edge (0, 4) is shared by 3 faces (numbered from 0); the mesh must be edge-manifold");
}

TEST_CASE("inconsistent orientation is rejected") {
  TriMesh m = akvf::test::grid_disk(3, 3);
  m.F.row(1) = Eigen::RowVector3i(m.F(1, 0), m.F(1, 2), m.F(1, 1));
  CHECK(validation_error(m) ==
        "m.obj: faces 0 and 1 traverse edge (0, 4) in the same direction (numbered from 0); faces must be consistently "
        "oriented");
}

TEST_CASE("repair: a face wound against its neighbours is reversed, its UV corners kept in the file's winding") {
  TriMesh m = akvf::test::grid_disk(3, 3);
  m.F.row(1) = Eigen::RowVector3i(m.F(1, 0), m.F(1, 2), m.F(1, 1));
  const akvf::DiskMesh repaired = akvf::prepare_disk_mesh(m, "m.obj", false, true);
  CHECK(repaired.reoriented_faces == std::vector<int>{1});  // the one face against most of its piece
  CHECK(repaired.mesh.F.row(1) == Eigen::RowVector3i(m.F(1, 0), m.F(1, 2), m.F(1, 1)));
  CHECK(repaired.warnings.back() ==
        "m.obj: repaired: reversed 1 face wound against their neighbours (1) (numbered from 0); their UV triangles "
        "run the other way in the file's winding (--repair none refuses such input)");
  // Through the API (repair auto by default): every corner as the file has it;
  // the reversed face is the one triangle whose UV runs the other way.
  const akvf::ParameterizeResult r = akvf::parameterize(m.V, m.F);
  CAPTURE(r.message);
  CHECK(akvf::is_normal_termination(r.status));
  CHECK(r.uv_faces == m.F);
  CHECK(akvf::count_inverted_triangles(r.uv_faces, r.uv) == 1);
  // A piece wound the other way throughout is left as it is.
  TriMesh reversed = akvf::test::grid_disk(3, 3);
  reversed.F.col(1).swap(reversed.F.col(2));
  CHECK(akvf::prepare_disk_mesh(reversed, "m.obj", false, true).reoriented_faces.empty());
  // Most of the piece decides: here the one face left as the file has it is reversed.
  TriMesh mostly = reversed;
  mostly.F.row(0) = m.F.row(0);
  CHECK(akvf::prepare_disk_mesh(mostly, "m.obj", false, true).reoriented_faces == std::vector<int>{0});
}

TEST_CASE("a Moebius strip is said to be non-orientable, and cut across where the windings disagree") {
  // A strip of 12 quads around a circle, its ends glued with a half twist.
  const int n = 12;
  TriMesh m;
  m.V.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const double t = 2 * M_PI * i / n, twist = t / 2;
    for (int side = 0; side < 2; ++side) {
      const double r = 2 + (side ? 0.5 : -0.5) * std::cos(twist), h = (side ? 0.5 : -0.5) * std::sin(twist);
      m.V.row(2 * i + side) << r * std::cos(t), r * std::sin(t), h;
    }
  }
  m.F.resize(2 * n, 3);
  for (int i = 0; i < n; ++i) {
    const int a = 2 * i, b = 2 * i + 1;
    // The last quad joins strip end i = n - 1 to the start with its sides swapped.
    const int c = i + 1 < n ? 2 * (i + 1) : 1, d = i + 1 < n ? 2 * (i + 1) + 1 : 0;
    m.F.row(2 * i) << a, c, d;
    m.F.row(2 * i + 1) << a, d, b;
  }
  CHECK(error_message([&] { akvf::prepare_disk_mesh(m, "m.obj", false, true); }) ==
        "m.obj: the surface is non-orientable (like a Moebius strip or a Klein bottle): no choice of face orientations "
        "agrees across every edge, so it has no UV map as one piece; cut auto cuts it where they disagree (akvf "
        "param --cut auto)");
  // With the cut: opened across once, the strip is a disk (one chart, one
  // boundary loop) with a copy of the cut edge's two ends.
  const akvf::DiskMesh disk = akvf::prepare_disk_mesh(m, "m.obj", true, true);
  CHECK(disk.num_charts() == 1);
  CHECK(disk.boundary_loops.size() == 1);
  CHECK(disk.mesh.num_vertices() == 2 * n + 2);
  REQUIRE(!disk.warnings.empty());
  CHECK(disk.warnings.front().find("non-orientable (like a Moebius strip or a Klein bottle); cut along 1 edge") !=
        std::string::npos);
  // Without repair it is refused as before.
  CHECK(error_message([&] {
          akvf::prepare_disk_mesh(m, "m.obj", true, false);
        }).find("repair auto with cut auto cuts it where they disagree (akvf param --repair auto --cut auto)") !=
        std::string::npos);
}

TEST_CASE("two fans meeting at a vertex are non-manifold") {
  // Two triangles touching at vertex 0 only.
  TriMesh m;
  m.V.resize(5, 3);
  m.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, -1, 0, 0, -1, -1, 0;
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 0, 3, 4;
  // They form one component only through vertex 0.
  CHECK(validation_error(m) ==
        "m.obj: vertex 0 (numbered from 0) is non-manifold: two separate boundary fans meet there");
  // Messages use the input's numbering even when unreferenced vertices are dropped.
  TriMesh padded = m;
  padded.V.conservativeResize(6, 3);
  padded.V.bottomRows(5) = m.V;
  padded.V.row(0) << 9, 9, 9;
  padded.F = m.F.array() + 1;
  CHECK(validation_error(padded) ==
        "m.obj: vertex 1 (numbered from 0) is non-manifold: two separate boundary fans meet there");
}

TEST_CASE("a zero-area face is rejected with its vertices") {
  TriMesh m = akvf::test::grid_disk(3, 3);
  m.V.row(4) = 0.5 * (m.V.row(0) + m.V.row(8));  // face 0 = (0, 1, 4)? make a collinear triple
  m.F.row(0) << 0, 4, 8;
  CHECK(validation_error(m).find("m.obj: face 0 (vertices 0, 4, 8) has zero area") == 0);
}

TEST_CASE("zero area is judged against the face's own edges, not the mesh's extent") {
  TriMesh m = akvf::test::grid_disk(3, 3);
  m.V.array() *= 0.25;  // faces of area 0.0078, then one vertex far away
  m.V.conservativeResize(10, 3);
  m.V.row(9) << 1e6, 1e6, 0;
  m.F.conservativeResize(m.F.rows() + 1, 3);
  m.F.row(m.F.rows() - 1) << 2, 9, 5;
  CHECK(validation_error(m) == "");
}

TEST_CASE("non-finite coordinates are rejected") {
  TriMesh m = akvf::test::grid_disk(3, 3);
  m.V(3, 1) = std::numeric_limits<double>::quiet_NaN();
  CHECK(validation_error(m) == "m.obj: vertex 3 has a non-finite coordinate (numbered from 0)");
}

TEST_CASE("a face that repeats a vertex is rejected") {
  TriMesh m = akvf::test::grid_disk(3, 3);
  m.F.row(2) << 1, 1, 5;
  CHECK(validation_error(m) == "m.obj: face 2 uses the same vertex twice (1, 1, 5) (numbered from 0)");
}

TEST_CASE("unreferenced vertices are dropped with a warning and mapped back") {
  TriMesh m = akvf::test::grid_disk(3, 3);
  TriMesh padded;
  padded.V.resize(m.num_vertices() + 2, 3);
  padded.V << Eigen::RowVector3d(9, 9, 9), m.V, Eigen::RowVector3d(7, 7, 7);
  padded.F = m.F.array() + 1;
  const auto disk = akvf::prepare_disk_mesh(padded, "p.obj");
  CHECK(disk.mesh.num_vertices() == 9);
  CHECK(disk.num_input_vertices == 11);
  CHECK(disk.input_vertex.front() == 1);
  CHECK(disk.input_vertex.back() == 9);
  REQUIRE(disk.warnings.size() == 1);
  CHECK(disk.warnings[0] ==
        "p.obj: dropped 2 unreferenced vertices (first: 0 (numbered from 0)); no face uses their UV: (0, 0) where one "
        "per vertex is written at the input's scale (the API's uv, PLY, --texture none)");
}

TEST_CASE("midpoint subdivision keeps a disk a disk and multiplies the faces by 4 per round") {
  const akvf::TriMesh grid = akvf::test::grid_disk(4, 3);
  const akvf::TriMesh fine = akvf::subdivide_midpoint(grid, 2);
  CHECK(fine.num_faces() == 16 * grid.num_faces());
  const akvf::DiskMesh disk = akvf::prepare_disk_mesh(fine, "fine");
  CHECK(disk.mesh.num_faces() == fine.num_faces());
  CHECK(akvf::surface_area(fine) == doctest::Approx(akvf::surface_area(grid)));
  const std::string expected = "would make " + std::to_string(64 * grid.num_faces()) + " faces (more than 100)";
  CHECK(akvf::test::error_message([&] { akvf::subdivide_midpoint(grid, 3, 100); }).find(expected) != std::string::npos);
}

TEST_CASE("repair: degenerate and repeated faces are set aside, numbered as in the file, and kept in the outputs") {
  TriMesh m = akvf::test::grid_disk(3, 3);
  const int faces = m.num_faces(), extra = m.num_vertices();
  m.V.conservativeResize(extra + 1, 3);
  m.V.row(extra) = 0.25 * m.V.row(0) + 0.75 * m.V.row(1);  // on the edge (0, 1)
  m.F.conservativeResize(faces + 3, 3);
  m.F.row(faces) << 0, extra, 1;                          // zero area; vertex `extra` only here
  m.F.row(faces + 1) << m.F(4, 1), m.F(4, 2), m.F(4, 0);  // face 4 again, rotated
  m.F.row(faces + 2) << 2, 2, 3;                          // a vertex twice
  CHECK(akvf::test::error_message([&] { akvf::prepare_disk_mesh(m, "m.obj"); }).find("uses the same vertex twice") !=
        std::string::npos);
  const akvf::DiskMesh disk = akvf::prepare_disk_mesh(m, "m.obj", false, true);
  CHECK(disk.removed_faces == std::vector<int>{faces, faces + 1, faces + 2});
  CHECK(disk.mesh.num_faces() == faces);
  CHECK(disk.mesh.num_vertices() == extra);
  CHECK(disk.per_corner_uv());
  REQUIRE(disk.warnings.size() == 1);
  CHECK(disk.warnings[0] ==
        "m.obj: set aside 3 faces the map cannot use (1 of zero area, 1 repeating an earlier face, 1 using a vertex "
        "twice; faces 8, 9, 10) (numbered from 0); the outputs keep them, their corners at their vertices' UVs "
        "(--repair none refuses them)");
  // Vertex `extra` is interpolated a quarter of the way from 1 to 0 (the next two corners of its face).
  const akvf::CornerSource& middle = disk.removed_corners[0][1];
  CHECK(disk.input_vertex[middle.a] == 1);
  CHECK(disk.input_vertex[middle.b] == 0);
  CHECK(middle.t == doctest::Approx(0.25));
  CHECK(disk.removed_corners[1][0].a == disk.removed_corners[1][0].b);

  // Through the API: every input face has its corners' UVs, the new corner
  // on its edge's map.
  const akvf::ParameterizeResult result = akvf::parameterize(m.V, m.F);
  REQUIRE(result.uv_faces.rows() == m.num_faces());
  const auto uv = [&](int f, int k) { return result.uv.row(result.uv_faces(f, k)).eval(); };
  CHECK((uv(faces, 1) - (0.75 * uv(faces, 2) + 0.25 * uv(faces, 0))).norm() < 1e-12);
  CHECK((uv(faces + 1, 0) - uv(4, 1)).norm() == 0);
  CHECK((uv(faces + 2, 0) - uv(faces + 2, 1)).norm() == 0);
  REQUIRE(!result.warnings.empty());
  CHECK(result.warnings[0].find("set aside 3 faces") != std::string::npos);
}

TEST_CASE("repair: vertices at one position in separate pieces are welded, so a triangle soup is one surface") {
  // A square as two triangles with three corners each (a soup, as an STL or
  // a model split along its own seams has it), and an unreferenced vertex.
  TriMesh soup;
  soup.V.resize(7, 3);
  soup.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 0, 0, 1, 1, 0, 0, 1, 0, 5, 5, 5;
  soup.F.resize(2, 3);
  soup.F << 0, 1, 2, 3, 4, 5;
  CHECK_FALSE(validation_error(soup).empty());  // without repair: two components, no cut
  const akvf::DiskMesh welded = akvf::prepare_disk_mesh(soup, "soup.obj", false, true);
  CHECK(welded.welding.welded == 2);
  CHECK(welded.welding.first_welded == std::vector<int>{3, 4});
  CHECK(welded.num_charts() == 1);
  CHECK(welded.mesh.num_vertices() == 4);
  CHECK(welded.num_input_vertices == 7);
  CHECK(welded.per_corner_uv());
  REQUIRE(welded.warnings.size() == 2);
  CHECK(welded.warnings[0].find("dropped 1 unreferenced vertices (first: 6") != std::string::npos);
  CHECK(welded.warnings[1] ==
        "soup.obj: welded 2 vertices onto an earlier vertex at the same position in another piece (3, 4) (numbered "
        "from 0); their corners take that vertex's UV (--repair none keeps them apart)");
  // Twins within one piece are the file's own seam: a grid slit from its
  // top edge to its centre (vertex 7 copied as 9 on the slit's right) stays
  // slit.
  TriMesh slit = akvf::test::grid_disk(3, 3);
  slit.V.conservativeResize(10, 3);
  slit.V.row(9) = slit.V.row(7);
  for (int f = 0; f < slit.num_faces(); ++f)
    if (slit.F(f, 0) == 4 && slit.F(f, 1) == 8 && slit.F(f, 2) == 7) slit.F(f, 2) = 9;
  const akvf::DiskMesh kept = akvf::prepare_disk_mesh(slit, "slit.obj", false, true);
  CHECK(kept.welding.welded == 0);
  CHECK(kept.mesh.num_vertices() == 10);
  CHECK(kept.boundary_loops[0].size() == 10);
  // The API's per-corner UV: the welded corners have their twins' UV.
  akvf::ParameterizeOptions options;
  const akvf::ParameterizeResult r = akvf::parameterize(soup.V, soup.F, options);
  REQUIRE(r.uv_faces.rows() == 2);
  CHECK(r.uv.row(r.uv_faces(1, 0)) == r.uv.row(r.uv_faces(0, 0)));
  CHECK(r.uv.row(r.uv_faces(1, 1)) == r.uv.row(r.uv_faces(0, 2)));
}

TEST_CASE("repair: a vertex where two fans meet is split, an edge of three faces opened, or both refused") {
  TriMesh bowtie;
  bowtie.V.resize(7, 3);
  bowtie.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 2, 1, 0.2, 2, 2, 0, 1, 2, 0;
  bowtie.F.resize(4, 3);
  bowtie.F << 0, 1, 2, 0, 2, 3, 2, 4, 5, 2, 5, 6;
  CHECK(validation_error(bowtie) ==
        "m.obj: vertex 2 (numbered from 0) is non-manifold: two separate boundary fans meet there");
  const akvf::DiskMesh split = akvf::prepare_disk_mesh(bowtie, "m.obj", true, true);
  CHECK(split.repair.split_vertices == 1);
  CHECK(split.repair.added_copies == 1);
  CHECK(split.repair.first_split == std::vector<int>{2});
  CHECK(split.per_corner_uv());
  CHECK(split.num_charts() == 2);
  CHECK(split.mesh.num_vertices() == 8);
  CHECK(split.input_vertex[7] == 2);  // the copy keeps its input vertex
  CHECK(split.warnings.back() ==
        "m.obj: repaired: split 1 non-manifold vertex (2) into one copy per fan of faces, 1 copy added (numbered "
        "from 0); the UV is per corner there (--repair none refuses such input)");
  // A fin: a third face on the diagonal of a square comes off, the square stays whole.
  TriMesh fin;
  fin.V.resize(5, 3);
  fin.V << 0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0.5, 0.5, 1;
  fin.F.resize(3, 3);
  fin.F << 0, 1, 2, 0, 2, 3, 0, 2, 4;
  CHECK(validation_error(fin).find("is shared by 3 faces") != std::string::npos);
  const akvf::DiskMesh opened = akvf::prepare_disk_mesh(fin, "m.obj", true, true);
  CHECK(opened.repair.opened_edges == 1);
  CHECK(opened.num_charts() == 2);
  // Fins on an edge of a vertex of many faces (the centre of a fan of 40)
  // and on a rim edge come off too, listed by their ends; of a rim edge's
  // two fins the one wound against the fan stays on it.
  TriMesh fan;
  const int rim = 40;
  fan.V.resize(rim + 4, 3);
  fan.V.row(0) << 0, 0, 0;
  for (int i = 1; i <= rim; ++i) fan.V.row(i) << std::cos(0.157 * i), std::sin(0.157 * i), 0;
  fan.V.row(rim + 1) << 0.5, 0.5, 1;
  fan.V.row(rim + 2) << 1, 1, 1;
  fan.V.row(rim + 3) << 1, 1, -1;
  fan.F.resize(rim + 3, 3);
  for (int i = 1; i <= rim; ++i) fan.F.row(i - 1) << 0, i, i % rim + 1;
  fan.F.row(rim) << 0, 5, rim + 1;
  fan.F.row(rim + 1) << 11, 10, rim + 2;
  fan.F.row(rim + 2) << 10, 11, rim + 3;
  const akvf::DiskMesh fins = akvf::prepare_disk_mesh(fan, "m.obj", true, true);
  CHECK(fins.repair.opened_edges == 2);
  CHECK(fins.repair.first_opened == std::vector<std::array<int, 2>>{{0, 5}, {10, 11}});
  CHECK(fins.num_charts() == 3);
  // A manifold mesh is left as it is.
  const akvf::DiskMesh grid = akvf::prepare_disk_mesh(akvf::test::grid_disk(5, 4), "grid.obj", false, true);
  CHECK_FALSE(grid.repair.any());
  CHECK_FALSE(grid.per_corner_uv());
}
