// gmsh .msh 2.2 and 4.1 ASCII: the same tetrahedra from both versions with
// other elements and sections skipped, and one test per malformed input
// naming the file, the line and the problem.
#include <doctest/doctest.h>

#include <sstream>

#include "akvf/deform.h"
#include "io/gmsh_reader.h"
#include "tests/test_support.h"

using akvf::test::error_message;

namespace {

// Two tets sharing a face; node tags 10, 20, ... (not 1..n), a triangle and
// a point element and a $PhysicalNames section around them.
const char* kMsh22 =
    "$MeshFormat\n2.2 0 8\n$EndMeshFormat\n"
    "$PhysicalNames\n1\n3 1 \"body\"\n$EndPhysicalNames\n"
    "$Nodes\n5\n10 0 0 0\n20 1 0 0\n30 0 1 0\n40 0 0 1\n50 1 1 1\n$EndNodes\n"
    "$Elements\n4\n1 15 2 0 1 10\n2 2 2 0 1 10 20 30\n3 4 2 1 1 10 20 30 40\n4 4 2 1 1 20 50 30 40\n$EndElements\n";

const char* kMsh41 =
    "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
    "$Entities\n1 0 0 1\n1 0 0 0 0\n1 0 0 0 1 1 1 0 0\n$EndEntities\n"
    "$Nodes\n2 5 10 50\n0 1 0 1\n10\n0 0 0\n3 1 0 4\n20\n30\n40\n50\n1 0 0\n0 1 0\n0 0 1\n1 1 1\n$EndNodes\n"
    "$Elements\n2 3 1 3\n2 1 2 1\n1 10 20 30\n3 1 4 2\n2 10 20 30 40\n3 20 50 30 40\n$EndElements\n";

akvf::TetMesh read(const std::string& text) {
  std::istringstream in(text);
  return akvf::read_gmsh(in, "m.msh");
}
std::string msh_error(const std::string& text) {
  return error_message([&] { read(text); });
}

}  // namespace

TEST_CASE("gmsh 2.2 and 4.1: the same tetrahedra, other elements and sections skipped") {
  const akvf::TetMesh a = read(kMsh22), b = read(kMsh41);
  REQUIRE(a.num_vertices() == 5);
  REQUIRE(a.num_tets() == 2);
  CHECK(a.V == b.V);
  CHECK(a.T == b.T);
  Eigen::MatrixXi expected(2, 4);
  expected << 0, 1, 2, 3, 1, 4, 2, 3;
  CHECK(a.T == expected);
  CHECK(a.V.row(4) == Eigen::RowVector3d(1, 1, 1));
}

TEST_CASE("gmsh: malformed files name the line and the problem") {
  CHECK(msh_error("hello\n") == "line 1 of m.msh: not a gmsh file (the first line must be '$MeshFormat')");
  CHECK(msh_error("$MeshFormat\n4.1 1 8\n$EndMeshFormat\n").find("line 2 of m.msh: binary .msh is not supported") == 0);
  CHECK(msh_error("$MeshFormat\n3.0 0 8\n$EndMeshFormat\n") ==
        "line 2 of m.msh: unsupported .msh version 3.0 (supported: 2.2 and 4.1, ASCII)");
  std::string missing = kMsh22;
  missing.replace(missing.find("20 50 30 40"), 11, "20 60 30 40");
  CHECK(msh_error(missing) == "line 21 of m.msh: tetrahedron uses node 60, which $Nodes does not define");
  std::string twice = kMsh22;
  twice.replace(twice.find("20 1 0 0"), 8, "10 1 0 0");
  CHECK(msh_error(twice) == "line 11 of m.msh: node 10 appears twice");
  std::string short_count = kMsh22;
  short_count.replace(short_count.find("$Nodes\n5"), 8, "$Nodes\n4");
  CHECK(msh_error(short_count).find("line 14 of m.msh: expected '$EndNodes'") == 0);
  std::string huge = kMsh41;
  huge.replace(huge.find("$Nodes\n2 5 10 50"), 16, "$Nodes\n2 2000000000 10 50");
  CHECK(msh_error(huge).find("the blocks hold 5 nodes, the $Nodes count says 2000000000") != std::string::npos);
  CHECK(msh_error("$MeshFormat\n2.2 0 8\n$EndMeshFormat\n$Nodes\n1\n1 0 0 0\n$EndNodes\n") ==
        "m.msh: no tetrahedra (element type 4)");
}

TEST_CASE("a gmsh mesh deforms like the same mesh from arrays") {
  const akvf::TetMesh mesh = read(kMsh41);
  akvf::PositionConstraints constraints;
  constraints.vertices = {0, 4};
  constraints.targets.resize(2, 3);
  constraints.targets << 0, 0, 0, 1.1, 1.1, 1.2;
  akvf::DeformOptions options;
  options.max_iters = 10;
  const akvf::DeformResult r = akvf::deform(mesh.V, mesh.T, constraints, options);
  CHECK(akvf::is_normal_termination(r.status));
  CHECK(r.x(4, 2) > 1.0);
}
