// Tet mesh readers (MEDIT, OBJ-like, .tet), writers and validation: each
// malformed input and invalid mesh with its message.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "akvf/tet_mesh_io.h"
#include "framework/mesh/tet_validation.h"
#include "tests/test_support.h"

using akvf::TetMesh;
using akvf::test::error_message;

namespace {

TetMesh medit(const std::string& text) {
  std::istringstream in(text);
  return akvf::read_medit(in, "m.mesh");
}
TetMesh tet_obj(const std::string& text) {
  std::istringstream in(text);
  return akvf::read_tet_obj(in, "m.obj");
}
TetMesh tet_file(const std::string& text) {
  std::istringstream in(text);
  return akvf::read_tet_file(in, "m.tet");
}

const std::string kMedit =
    "MeshVersionFormatted 1\nDimension\n3\nVertices\n5\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\n1 1 1 0\n"
    "Triangles\n1\n1 2 3 0\nTetrahedra\n2\n1 2 3 4 0\n2 3 4 5 0\nEnd\n";

// Two positively oriented tets sharing the face (1, 2, 3).
TetMesh two_tets() { return medit(kMedit); }

std::string validation_error(const TetMesh& mesh) {
  return error_message([&] { akvf::prepare_tet_mesh(mesh, "m", nullptr); });
}

}  // namespace

TEST_CASE("MEDIT: vertices and tetrahedra are read, other sections skipped") {
  const TetMesh mesh = two_tets();
  CHECK(mesh.num_vertices() == 5);
  REQUIRE(mesh.num_tets() == 2);
  CHECK(mesh.T.row(1) == Eigen::RowVector4i(1, 2, 3, 4));
}

TEST_CASE("MEDIT: malformed files name the line and the problem") {
  CHECK(error_message([] { medit("Dimension 2\n"); }) == "line 1 of m.mesh: dimension 2: only 3 is supported");
  CHECK(error_message([] { medit("Vertices\n2\n0 0 0 0\n"); }) == "line 3 of m.mesh: file ends after 1 of 2 vertices");
  CHECK(error_message([] { medit("Vertices\n1\n0 x 0 0\n"); }) ==
        "line 3 of m.mesh: vertex coordinate 'x' is not a finite number");
  CHECK(error_message([] { medit("Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 9 0\n"); }) ==
        "line 9 of m.mesh: tet 1 uses vertex 9, out of range (4 vertices) (numbered from 1, as in the file)");
  CHECK(error_message([] { medit("Vertices\n1\n0 0 0 0\nTetrahedra\n1\n1 2 3\n"); }) ==
        "line 6 of m.mesh: tetrahedra row has 3 numbers, expected 4");
  CHECK(error_message([] { medit("Vertices\n1\n0 0 0 0\nTetrahedra\n1\n0 1 1 1 0\n"); }) ==
        "line 6 of m.mesh: tet vertex index 0 is out of range");
  CHECK(error_message([] { medit("42\n"); }) ==
        "line 1 of m.mesh: expected a section keyword (Vertices, Tetrahedra, ...), found '42'");
  CHECK(error_message([] { medit("Vertices\n-1\n"); }) == "line 2 of m.mesh: Vertices count must be >= 0, found -1");
  CHECK(error_message([] { medit("Vertices\n1\n0 0 0 0\nEnd\n"); }) == "m.mesh: no tetrahedra");
  // Counts are never trusted for allocation: 10^12 rows fail at the end of the file, at once.
  CHECK(error_message([] { medit("Vertices\n1000000000000\n0 0 0 0\n"); }) ==
        "line 3 of m.mesh: file ends after 1 of 1000000000000 vertices");
}

TEST_CASE("OBJ-like tets: `f a b c d`, 1-based, other corner counts are rejected") {
  const TetMesh mesh = tet_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3 4\n");
  CHECK(mesh.num_tets() == 1);
  CHECK(mesh.T.row(0) == Eigen::RowVector4i(0, 1, 2, 3));
  CHECK(error_message([] { tet_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"); }) ==
        "line 4 of m.obj: tet has 3 corners; expected 4 (one tetrahedron per `f` line)");
  CHECK(error_message([] { tet_obj("v 0 0 0\nf 1 2 3 7\n"); }) ==
        "line 2 of m.obj: tet index 2 out of range (1 vertices)");
}

TEST_CASE(".tet: header counts, then 0-based rows") {
  const TetMesh mesh = tet_file("#num of vertex: 4\n#num of tetrahedra: 1\n0 0 0\n1 0 0\n0 1 0\n\n0 0 1\n0 1 2 3\n");
  CHECK(mesh.num_vertices() == 4);
  CHECK(mesh.T.row(0) == Eigen::RowVector4i(0, 1, 2, 3));
  CHECK(error_message([] { tet_file("#vertices 4\n"); }) ==
        "line 1 of m.tet: expected '#num of vertex: N', found '#vertices 4'");
  CHECK(error_message([] { tet_file("#num of vertex: 4\n#num of tetrahedra: 1\n0 0 0\n"); }) ==
        "line 3 of m.tet: file ends after 1 of 4 vertices");
  CHECK(error_message([] {
          tet_file("#num of vertex: 4\n#num of tetrahedra: 1000000000000\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n");
        }) == "line 6 of m.tet: file ends after 0 of 1000000000000 tetrahedra");
  CHECK(error_message([] {
          tet_file("#num of vertex: 4\n#num of tetrahedra: 1\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 1 2 4\n");
        }) == "line 7 of m.tet: tet 0 uses vertex 4, out of range (4 vertices) (numbered from 0)");
}

TEST_CASE("unknown tet formats and missing files are reported") {
  CHECK(error_message([] { akvf::read_tet_mesh("x.vtk"); }) ==
        "x.vtk: unsupported tet mesh format '.vtk' (expected .mesh, .msh, .obj or .tet)");
  CHECK(error_message([] { akvf::read_tet_mesh("/nonexistent/x.mesh"); }) ==
        "/nonexistent/x.mesh: cannot open: No such file or directory");
}

TEST_CASE("writers round-trip through MEDIT and write a VTK unstructured grid") {
  const TetMesh mesh = two_tets();
  const auto dir = std::filesystem::temp_directory_path();
  const std::string medit_path = (dir / "akvf_tet_roundtrip.mesh").string();
  const std::string vtk_path = (dir / "akvf_tet_roundtrip.vtk").string();
  akvf::write_medit(medit_path, mesh);
  akvf::write_vtk(vtk_path, mesh);
  const TetMesh again = akvf::read_tet_mesh(medit_path);
  CHECK(again.V == mesh.V);
  CHECK(again.T == mesh.T);
  std::ifstream vtk(vtk_path);
  const std::string text((std::istreambuf_iterator<char>(vtk)), std::istreambuf_iterator<char>());
  CHECK(text.find("DATASET UNSTRUCTURED_GRID\nPOINTS 5 double\n") != std::string::npos);
  CHECK(text.find("CELLS 2 10\n4 0 1 2 3\n4 1 2 3 4\nCELL_TYPES 2\n10\n10\n") != std::string::npos);
  std::filesystem::remove(medit_path);
  std::filesystem::remove(vtk_path);
}

TEST_CASE("tet validation: orientation, degeneracy, components, indices") {
  akvf::Warnings warnings;
  const TetMesh ok = akvf::prepare_tet_mesh(two_tets(), "m", &warnings).mesh;
  CHECK(warnings.empty());
  CHECK(akvf::signed_tet_volume(ok, 0) > 0);

  TetMesh inverted = two_tets();
  inverted.T.col(0).swap(inverted.T.col(1));
  const TetMesh fixed = akvf::prepare_tet_mesh(inverted, "m", &warnings).mesh;
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0] == "m: every tet was negatively oriented; flipped them all");
  CHECK(akvf::signed_tet_volume(fixed, 0) > 0);
  CHECK(akvf::signed_tet_volume(fixed, 1) > 0);

  TetMesh mixed = two_tets();
  mixed.T.row(1) = Eigen::RowVector4i(2, 1, 3, 4);
  CHECK(validation_error(mixed) ==
        "m: inconsistent orientation: tet 1 is positively oriented but tet 2 negatively (numbered from 1, as in the "
        "file); "
        "every tet must have the same "
        "orientation");

  TetMesh flat = two_tets();
  flat.V.row(4) << 0.5, 0.5, 0;  // in the plane of vertices 1, 2 and ... make tet 1 flat
  flat.V.row(3) << 0.25, 0.25, 0;
  CHECK(validation_error(flat).find("m: tet 1 is degenerate (volume ") == 0);

  TetMesh repeated = two_tets();
  repeated.T(1, 3) = 1;
  CHECK(validation_error(repeated) == "m: tet 2 uses vertex 2 twice (numbered from 1, as in the file)");

  TetMesh apart = two_tets();
  apart.V.conservativeResize(9, 3);
  apart.V.bottomRows(4) = apart.V.topRows(4).rowwise() + Eigen::RowVector3d(5, 0, 0);
  apart.T.row(1) = Eigen::RowVector4i(5, 6, 7, 8);
  CHECK(validation_error(apart) == "m: mesh has 2 connected components; deform one component at a time");
}

TEST_CASE("the shared tet meshes read and validate with their documented sizes") {
  const std::string dir = akvf::test::data_dir();
  if (dir.empty()) return akvf::test::skip("../shared/meshes not found (set AKVF_DATA_DIR)");
  struct Expected {
    const char* file;
    int vertices, tets;
  };
  for (const Expected& e : {Expected{"cube_4k.obj", 1000, 4374}, Expected{"cube_40k.obj", 9261, 48000},
                            Expected{"octopus-low.mesh", 452, 1140}, Expected{"bar.tet", 2152, 8118}}) {
    CAPTURE(e.file);
    const TetMesh mesh = akvf::read_tet_mesh(dir + "/tet/" + e.file);
    CHECK(mesh.num_vertices() == e.vertices);
    CHECK(mesh.num_tets() == e.tets);
    akvf::Warnings warnings;
    const TetMesh valid = akvf::prepare_tet_mesh(mesh, e.file, &warnings).mesh;
    for (int t = 0; t < valid.num_tets(); ++t) REQUIRE(akvf::signed_tet_volume(valid, t) > 0);
  }
}
