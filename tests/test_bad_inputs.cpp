// The remaining bad inputs of issue 11: byte-order marks in every text format
// we read, OFF counts that disagree with the file, OBJ statements we skip,
// vertices with extra tokens, elements numbered as the file numbers them,
// unreferenced and repeated tet vertices. Each case checks the message.
#include <doctest/doctest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "akvf/internal/deformation.h"
#include "akvf/internal/parameterization.h"
#include "akvf/mesh_io.h"
#include "akvf/tet_mesh_io.h"
#include "experiments/report/trace_csv.h"
#include "experiments/runner/manifest.h"
#include "framework/mesh/tet_validation.h"
#include "io/constraints_io.h"
#include "tests/cli_support.h"
#include "tests/test_support.h"

namespace fs = std::filesystem;
using akvf::test::error_message;

namespace {

const std::string kBom = "\xEF\xBB\xBF";

// A square of two triangles; with `unused`, a fifth vertex no face uses.
std::string square_obj(bool unused) {
  return std::string("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n") + (unused ? "v 5 5 5\n" : "") + "f 1 2 3\nf 1 3 4\n";
}

akvf::TriMesh obj(const std::string& text, akvf::Warnings* warnings = nullptr) {
  std::istringstream in(text);
  return akvf::read_obj(in, "m.obj", warnings);
}

akvf::TriMesh off(const std::string& text) {
  std::istringstream in(text);
  return akvf::read_off(in, "m.off");
}

fs::path scratch(const std::string& name) { return akvf::test::scratch_dir("bad_inputs_" + name); }

}  // namespace

TEST_CASE("a UTF-8 byte-order mark is skipped in OBJ: no vertex is lost") {
  const akvf::TriMesh plain = obj(square_obj(true)), marked = obj(kBom + square_obj(true));
  CHECK(marked.num_vertices() == 5);
  CHECK(marked.V == plain.V);
  CHECK(marked.F == plain.F);
  CHECK(obj(kBom + square_obj(false)).num_vertices() == 4);
}

TEST_CASE("a UTF-8 byte-order mark is skipped in OFF, MEDIT, .tet and constraints") {
  CHECK(off(kBom + "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n").num_faces() == 2);
  const std::string tets = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3 4\n";
  std::istringstream tet_obj(kBom + tets);
  CHECK(akvf::read_tet_obj(tet_obj, "m.obj").num_vertices() == 4);
  std::istringstream medit(kBom + "Vertices\n4\n0 0 0 0\n1 0 0 0\n0 1 0 0\n0 0 1 0\nTetrahedra\n1\n1 2 3 4 0\nEnd\n");
  CHECK(akvf::read_medit(medit, "m.mesh").num_tets() == 1);
  std::istringstream tet(kBom + "#num of vertex: 4\n#num of tetrahedra: 1\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n0 1 2 3\n");
  CHECK(akvf::read_tet_file(tet, "m.tet").num_tets() == 1);
  std::istringstream constraints(kBom + "0 1 2 3\n");
  const akvf::PositionConstraints c = akvf::read_constraints(constraints, "c.txt", 4);
  REQUIRE(c.vertices.size() == 1);
  CHECK(c.vertices[0] == 0);
}

TEST_CASE("a UTF-8 byte-order mark is skipped in manifests and in traces read by plot") {
  const std::string manifest =
      R"({"name": "bom", "meshes": [{"label": "a", "missing": "not here"}], "methods": [{"label": "m"}]})";
  CHECK(akvf::parse_manifest(kBom + manifest, "m.json").name == "bom");
  const fs::path dir = scratch("trace");
  std::ofstream(dir / "t.csv") << kBom << "iter,energy,status\n0,5,\n1,4,converged\n";
  const akvf::TraceTable table = akvf::read_trace_csv((dir / "t.csv").string());
  CHECK(table.column("iter", "t.csv").size() == 2);
  fs::remove_all(dir);
}

TEST_CASE("an OFF face count that disagrees with the file is an error naming the line") {
  const std::string body = "0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n";
  CHECK(error_message([&] { off("OFF\n4 1 0\n" + body); }) ==
        "line 8 of m.off: more faces than the header's face count 1 (or stray text after the last face); fix the "
        "count on the header line");
  CHECK(error_message([&] { off("OFF\n4 3 0\n" + body); }) == "line 8 of m.off: file ends after 2 of 3 faces");
  CHECK(off("OFF\n4 2 0\n" + body + "\n# trailing comment\n").num_faces() == 2);
}

TEST_CASE("OBJ: the statements OBJ allows are skipped quietly, unknown ones with one warning per kind") {
  akvf::Warnings warnings;
  const std::string allowed =
      "mtllib m.mtl\no thing\ng group\ns off\nusemtl red\nvt 0 0\nvn 0 0 1\nvp 0.5\nl 1 2\np 1\n";
  CHECK(obj(allowed + square_obj(false), &warnings).num_faces() == 2);
  CHECK(warnings.empty());
  obj("foo 1\n" + square_obj(false) + "foo 2\nbar\n", &warnings);
  REQUIRE(warnings.size() == 2);
  CHECK(warnings[0] == "line 9 of m.obj: unknown OBJ statement 'bar' ignored (1 line)");
  CHECK(warnings[1] == "line 1 of m.obj: unknown OBJ statement 'foo' ignored (2 lines)");
}

TEST_CASE("OBJ: a vertex takes x y z, a weight w, or a colour, other extra tokens are refused") {
  CHECK(obj("v 0 0 0 1\nv 1 0 0 1\nv 0 1 0 1\nf 1 2 3\n").num_vertices() == 3);
  CHECK(obj("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n").num_vertices() == 3);
  CHECK(error_message([] { obj("v 0 0 0 junk\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"); }) ==
        "line 1 of m.obj: vertex weight w 'junk' is not a finite number");
  CHECK(error_message([] { obj("v 0 0 0\nv 1 0 0 1 2\nv 0 1 0\nf 1 2 3\n"); }) ==
        "line 2 of m.obj: vertex has 5 numbers; expected x y z, x y z w, or x y z r g b (extra tokens after the "
        "coordinates)");
}

TEST_CASE("validation names vertices and faces as the file numbers them") {
  // Three faces around edge (1, 2) in OBJ numbering: 1-based in the message
  // (repair none: the edge is refused rather than opened).
  akvf::ParamConfig no_repair;
  no_repair.repair = false;
  const std::string fan = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nf 1 2 3\nf 2 1 4\nf 1 2 5\n";
  const std::string obj_message = error_message([&] { akvf::prepare_parameterization(obj(fan), "m.obj", no_repair); });
  CHECK(obj_message ==
        "m.obj: edge (1, 2) is shared by 3 faces (numbered from 1, as in the file); the mesh must be "
        "edge-manifold");
  // The same mesh as OFF: numbered from 0.
  const std::string off_message = error_message([&] {
    akvf::prepare_parameterization(off("OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n"),
                                   "m.off", no_repair);
  });
  CHECK(off_message == "m.off: edge (0, 1) is shared by 3 faces (numbered from 0); the mesh must be edge-manifold");
  // A degenerate face after an unreferenced vertex: the file's numbers, not the compacted ones.
  const std::string degenerate = "v 9 9 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 2 0 0\nf 2 3 4\nf 2 3 5\n";
  CHECK(error_message([&] { akvf::prepare_parameterization(obj(degenerate), "d.obj", no_repair); }) ==
        "d.obj: face 2 (vertices 2, 3, 5) has zero area (numbered from 1, as in the file); remove degenerate faces "
        "first (--repair auto sets them aside)");
}

TEST_CASE("a tet mesh with an unreferenced vertex deforms with every factored method, the output keeps numbering") {
  akvf::TetMesh mesh = akvf::test::tet_grid(2);
  const int extra = mesh.num_vertices();
  mesh.V.conservativeResize(extra + 1, 3);
  mesh.V.row(extra) << 7, 7, 7;  // in no tet
  // Swap it into the middle of the numbering, so the renumbering is visible.
  mesh.V.row(extra).swap(mesh.V.row(3));
  mesh.T = mesh.T.unaryExpr([&](int v) { return v == 3 ? extra : v; }).eval();
  akvf::PositionConstraints constraints;
  constraints.vertices = {0, extra};
  constraints.targets.resize(2, 3);
  constraints.targets.row(0) = mesh.V.row(0) + Eigen::RowVector3d(0.1, 0, 0);
  constraints.targets.row(1) = mesh.V.row(extra);
  for (const char* method : {"akvf", "newton", "slim", "laplacian"}) {
    CAPTURE(method);
    akvf::DeformConfig config;
    config.preconditioner = method;
    config.optimizer.max_iterations = 5;
    const akvf::DeformRun run = akvf::run_deformation(mesh, "u.mesh", constraints, config);
    CHECK(akvf::is_normal_termination(run.result.status));
    REQUIRE(run.warnings.size() == 1);
    CHECK(run.warnings[0] ==
          "u.mesh: dropped 1 vertices that are in no tet (first: 3 (numbered from 0)); they keep their positions in "
          "the output");
    const akvf::TetMesh out = run.prepared.in_input_numbering(akvf::unstack_rows(run.result.x, 3), mesh);
    CHECK(out.num_vertices() == mesh.num_vertices());
    CHECK(out.V.row(3) == mesh.V.row(3));  // the unreferenced vertex stays put
    CHECK(out.T == mesh.T);
    CHECK(out.V(0, 0) > mesh.V(0, 0));  // pulled towards its target
  }
}

TEST_CASE("repeated tets and coincident tet vertices are accepted with a warning") {
  akvf::TetMesh mesh = akvf::test::tet_grid(1);
  mesh.T.conservativeResize(mesh.num_tets() + 1, 4);
  const Eigen::RowVector4i first = mesh.T.row(0);
  mesh.T.row(mesh.num_tets() - 1) << first(1), first(2), first(0), first(3);  // an even permutation: same tet
  akvf::Warnings warnings;
  akvf::prepare_tet_mesh(mesh, "r.mesh", &warnings);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].find("r.mesh: 1 tets repeat the vertices of another (first: tet 6 repeats tet 0") == 0);

  akvf::TetMesh cracked = akvf::test::tet_grid(1);
  cracked.V.conservativeResize(cracked.num_vertices() + 1, 3);
  cracked.V.row(cracked.num_vertices() - 1) = cracked.V.row(7);
  cracked.T(5, 3) = cracked.T(5, 3) == 7 ? cracked.num_vertices() - 1 : cracked.T(5, 3);
  for (int k = 0; k < 4; ++k)
    if (cracked.T(5, k) == 7) cracked.T(5, k) = cracked.num_vertices() - 1;
  warnings.clear();
  akvf::prepare_tet_mesh(cracked, "c.mesh", &warnings);
  REQUIRE(warnings.size() == 1);
  CHECK(warnings[0].find("c.mesh: 1 vertices are at exactly the position of another (first: vertex 8 is at the "
                         "position of vertex 7") == 0);
}
