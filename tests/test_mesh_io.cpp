// OBJ and OFF readers: every corner form, and one test per malformed input
// that checks the message names the file, the line and the problem.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "akvf/mesh_io.h"
#include "io/polygon_triangulation.h"
#include "tests/cli_support.h"
#include "tests/test_support.h"

using akvf::test::error_message;
using akvf::test::parse_mesh;

namespace {
std::string obj_error(const std::string& text) {
  return error_message([&] { parse_mesh(text, "bad.obj"); });
}
std::string off_error(const std::string& text) {
  return error_message([&] { parse_mesh(text, "bad.off"); });
}
const std::string kSquareVertices = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n";
}  // namespace

TEST_CASE("OBJ reads every face corner form and ignores vt and vn") {
  const auto mesh = parse_mesh(kSquareVertices +
                                   "vt 0 0\nvn 0 0 1\n# comment\ng group\nusemtl m\n"
                                   "f 1 2/1 3//1\nf 1/1/1 -2/1 -1\n",
                               "square.obj");
  REQUIRE(mesh.num_vertices() == 4);
  REQUIRE(mesh.num_faces() == 2);
  CHECK(mesh.F.row(0) == Eigen::RowVector3i(0, 1, 2));
  CHECK(mesh.F.row(1) == Eigen::RowVector3i(0, 2, 3));  // -2 and -1 relative to 4 vertices
  CHECK(mesh.V(2, 0) == 1.0);
}

TEST_CASE("OBJ triangulates faces with more than three corners, with a warning") {
  std::istringstream in(kSquareVertices + "v 2 0.5 0\nf 1 2 5 3 4\n");
  akvf::Warnings warnings;
  const akvf::TriMesh mesh = akvf::read_obj(in, "pentagon.obj", &warnings);
  REQUIRE(mesh.num_faces() == 3);
  CHECK(warnings == akvf::Warnings{"pentagon.obj: triangulated 1 face with more than three corners (up to 5) into "
                                   "triangles; 3 triangles in all, numbered in messages as triangles"});
  for (int f = 0; f < 3; ++f) {  // every triangle keeps the pentagon's orientation (+z)
    const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
    CHECK((b - a).cross(c - a).z() > 0);
  }
}

TEST_CASE("OBJ rejects faces with fewer than three corners") {
  CHECK(obj_error(kSquareVertices + "f 1 2\n") == "line 5 of bad.obj: face has 2 corners; a face needs at least three");
}

TEST_CASE("OBJ rejects an index out of range, naming its line") {
  CHECK(obj_error(kSquareVertices + "f 1 2 3\nf 1 3 9\n") ==
        "line 6 of bad.obj: face index 9 out of range (4 vertices)");
}

TEST_CASE("OBJ rejects index zero") {
  CHECK(obj_error(kSquareVertices + "f 0 1 2\n") ==
        "line 5 of bad.obj: face corner '0': OBJ indices start at 1, not 0");
}

TEST_CASE("OBJ rejects a relative index before the first vertex") {
  CHECK(obj_error(kSquareVertices + "f -5 1 2\n") ==
        "line 5 of bad.obj: relative face index -5 reaches before the first vertex (4 vertices so far)");
}

TEST_CASE("OBJ rejects a corner that is not a number") {
  CHECK(obj_error(kSquareVertices + "f a 1 2\n") ==
        "line 5 of bad.obj: face corner 'a' does not start with a vertex index (a whole number)");
  CHECK(obj_error(kSquareVertices + "f 1e20 1 2\n") ==
        "line 5 of bad.obj: face corner '1e20' does not start with a vertex index (a whole number)");
}

TEST_CASE("OBJ names a huge index as it is written") {
  CHECK(obj_error(kSquareVertices + "f 1 2 2147483648\n") ==
        "line 5 of bad.obj: face index 2147483648 out of range (4 vertices)");
  CHECK(obj_error(kSquareVertices + "f 1 2 99999999999999999999999\n") ==
        "line 5 of bad.obj: face index 99999999999999999999999 is too large");
}

TEST_CASE("OBJ in UTF-16 is named as such, not as a file without vertices") {
  std::string utf16 = "\xFF\xFE";
  for (char c : kSquareVertices + "f 1 2 3\n") utf16 += std::string{c, '\0'};
  CHECK(obj_error(utf16) == "line 1 of bad.obj: the file is UTF-16; save it as UTF-8 or ASCII");
  CHECK(obj_error(utf16.substr(2)).find("line 1 of bad.obj: a NUL byte: the file is not text") == 0);
}

TEST_CASE("OBJ rejects a bad or non-finite coordinate") {
  CHECK(obj_error("v 0 0 0\nv 1 x 0\n") == "line 2 of bad.obj: vertex coordinate 'x' is not a finite number");
  CHECK(obj_error("v 0 nan 0\n") == "line 1 of bad.obj: vertex coordinate 'nan' is not a finite number");
  CHECK(obj_error("v 0 0 inf\n") == "line 1 of bad.obj: vertex coordinate 'inf' is not a finite number");
  CHECK(obj_error("v 0 1e999 0\n") == "line 1 of bad.obj: vertex coordinate '1e999' is not a finite number");
}

TEST_CASE("OBJ rejects a vertex with too few coordinates") {
  CHECK(obj_error("v 0 0\n") == "line 1 of bad.obj: vertex needs three coordinates, found 2");
}

TEST_CASE("OBJ without faces or vertices is an error") {
  CHECK(obj_error(kSquareVertices) == "bad.obj: no faces");
  CHECK(obj_error("# nothing\n") == "bad.obj: no vertices");
}

TEST_CASE("OFF reads header, counts, comments and faces") {
  const auto mesh = parse_mesh("OFF\n# comment\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 0 2 3\n", "sq.off");
  CHECK(mesh.num_vertices() == 4);
  CHECK(mesh.num_faces() == 2);
  const auto inline_counts = parse_mesh("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "tri.off");
  CHECK(inline_counts.num_faces() == 1);
}

TEST_CASE("OFF rejects a wrong header") {
  CHECK(off_error("PLY\n3 1 0\n") == "line 1 of bad.off: expected an 'OFF' header, found 'PLY'");
  CHECK(off_error("") == "bad.off: empty file (expected an 'OFF' header)");
}

TEST_CASE("OFF rejects bad counts") {
  CHECK(off_error("OFF\nthree 1 0\n") == "line 2 of bad.off: vertex count 'three' is not an integer");
  CHECK(off_error("OFF\n-3 1 0\n") == "line 2 of bad.off: vertex count must be positive, found -3");
  CHECK(off_error("OFF\n3 0 0\n") == "line 2 of bad.off: face count must be positive, found 0");
}

TEST_CASE("OFF that declares more rows than it has fails fast without allocating them") {
  CHECK(off_error("OFF\n1000000000000 1 0\n0 0 0\n") ==
        "line 2 of bad.off: the counts (1000000000000 vertices, 1 face) are too large");
  CHECK(off_error("OFF\n2000000 1 0\n0 0 0\n") == "line 3 of bad.off: file ends after 1 of 2000000 vertices");
  CHECK(off_error("OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") == "line 6 of bad.off: file ends after 1 of 2 faces");
}

TEST_CASE("OFF triangulates polygons, rejects short faces and bad indices") {
  const std::string head = "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n";
  CHECK(parse_mesh(head + "4 0 1 2 3\n", "quad.off").num_faces() == 2);
  CHECK(off_error(head + "2 0 1\n") == "line 7 of bad.off: face has 2 corners; a face needs at least three");
  CHECK(off_error(head + "3 0 1\n") == "line 7 of bad.off: face lists fewer than its 3 vertex indices");
  CHECK(off_error(head + "3 0 1 4\n") == "line 7 of bad.off: face index 4 out of range (4 vertices)");
  CHECK(off_error(head + "3 0 -1 2\n") == "line 7 of bad.off: face index -1 out of range (4 vertices)");
}

TEST_CASE("reading a file checks the extension and that it exists") {
  CHECK(error_message([] { akvf::read_triangle_mesh("mesh.3ds"); }) ==
        "mesh.3ds: unsupported mesh format '.3ds' (expected .obj, .off, .ply or .stl)");
  CHECK(error_message([] { akvf::read_triangle_mesh("/nonexistent/cow.obj"); }) ==
        "/nonexistent/cow.obj: cannot open: No such file or directory");
}

TEST_CASE("OBJ writer keeps vertices and faces and adds one vt per vertex") {
  const auto mesh = parse_mesh(kSquareVertices + "f 1 2 3\nf 1 3 4\n", "square.obj");
  Eigen::MatrixXd UV(4, 2);
  UV << 0, 0, 2, 0, 2, 2, 0, 2;
  const auto path = (std::filesystem::temp_directory_path() / "akvf_writer_test.obj").string();
  akvf::write_obj_with_uv(path, mesh, UV);
  std::ifstream in(path);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  CHECK(text.find("vt 2 2\n") != std::string::npos);
  CHECK(text.find("f 1/1 3/3 4/4\n") != std::string::npos);
  std::istringstream again(text);
  const auto reread = akvf::read_obj(again, path);
  CHECK(reread.F == mesh.F);
  CHECK(reread.V == mesh.V);
  std::filesystem::remove(path);
}

TEST_CASE("OBJ writer keeps what the source carries besides: normals, groups, materials, colours, lines") {
  const std::string source =
      "mtllib a.mtl\no square\nv 0 0 0 1 0 0\nv 1 0 0\nv 1 1 0 0 0 1\nv 0 1 0\nvn 0 0 1\nvt 5 5\n"
      "g top\nusemtl red\ns 1\nf 1 2//1 3/1/1\nusemtl blue\nf -4/1/1 -2 -1//-1\nl 1/1 2/1\n";
  std::istringstream in(source);
  akvf::ObjPassthrough passthrough;
  const akvf::TriMesh mesh = akvf::read_obj(in, "square.obj", nullptr, nullptr, &passthrough);
  CHECK(passthrough.material_libraries == std::vector<std::string>{"a.mtl"});
  Eigen::MatrixXd UV(4, 2);
  UV << 0, 0, 2, 0, 2, 2, 0, 2;
  const auto path = (std::filesystem::temp_directory_path() / "akvf_passthrough_test.obj").string();
  auto written = [&] { return akvf::test::read_text(path); };
  akvf::write_obj_with_uv(path, mesh, UV, "", &passthrough);
  CHECK(written() ==
        "# 4 vertices, 2 faces, written by akvf\nmtllib a.mtl\no square\nv 0 0 0 1 0 0\nv 1 0 0\nv 1 1 0 0 0 1\n"
        "v 0 1 0\nvn 0 0 1\ng top\nusemtl red\ns 1\nvt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\nf 1/1 2/2/1 3/3/1\nusemtl blue\n"
        "f 1/1/1 3/3 4/4/1\nl 1 2\n");
  // With a material of its own, the source's libraries and materials give way.
  akvf::write_obj_with_uv(path, mesh, UV, "uv.mtl", &passthrough);
  CHECK(written() ==
        "# 4 vertices, 2 faces, written by akvf\nmtllib uv.mtl\no square\nv 0 0 0 1 0 0\nv 1 0 0\nv 1 1 0 0 0 1\n"
        "v 0 1 0\nvn 0 0 1\ng top\ns 1\nvt 0 0\nvt 2 0\nvt 2 2\nvt 0 2\nusemtl checker\nf 1/1 2/2/1 3/3/1\n"
        "f 1/1/1 3/3 4/4/1\nl 1 2\n");
  std::filesystem::remove(path);
}

TEST_CASE("a quad split along its shorter diagonal, a concave polygon by ears inside it") {
  Eigen::MatrixXd V(4, 3);
  V << 0, 0, 0, 3, 0, 0, 3.2, 1, 0, 0, 1, 0;  // diagonal 0-2 is longer than 1-3
  auto triangles = akvf::triangulate_polygon(V, {0, 1, 2, 3});
  REQUIRE(triangles.size() == 2);
  for (const auto& t : triangles) CHECK(std::count(t.begin(), t.end(), 1) + std::count(t.begin(), t.end(), 3) == 2);
  // An arrow (reflex corner at 3): no triangle may cover the notch.
  Eigen::MatrixXd arrow(5, 3);
  arrow << 0, 0, 0, 2, 0, 0, 2, 2, 0, 1, 0.5, 0, 0, 2, 0;
  triangles = akvf::triangulate_polygon(arrow, {0, 1, 2, 3, 4});
  REQUIRE(triangles.size() == 3);
  double area = 0;
  for (const auto& t : triangles) {
    const Eigen::Vector3d a = arrow.row(t[0]), b = arrow.row(t[1]), c = arrow.row(t[2]);
    const double z = (b - a).cross(c - a).z();
    CHECK(z > 0);
    area += 0.5 * z;
  }
  CHECK(area == doctest::Approx(2 * 2 - 0.5 * 2 * 1.5));  // the square less the notch
}

TEST_CASE("a quad is not split along a diagonal that another face has as a side") {
  // Triangle (a, b, v) and quad (v, b, c, a) around v, raised: projected on
  // the quad's plane v is a convex corner and a-b the shorter diagonal, but
  // a-b is the triangle's side, and a third face on it would make the edge
  // non-manifold; the quad takes v-c.
  const std::string source = "v 0 0 0\nv 1 0 0\nv 0.5 3 0\nv 0.5 -0.2 1.5\nf 1 2 4\nf 4 2 3 1\n";
  std::istringstream in(source);
  const akvf::TriMesh mesh = akvf::read_obj(in, "fan.obj");
  REQUIRE(mesh.num_faces() == 3);
  for (int f = 1; f < 3; ++f) {
    const std::set<int> corners = {mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2)};
    CHECK(corners.count(3) + corners.count(2) == 2);  // v and c: 0-based 3 and 2
  }
  // Without the mesh's other faces, the shorter diagonal a-b.
  const auto alone = akvf::triangulate_polygon(mesh.V, {3, 1, 2, 0});
  REQUIRE(alone.size() == 2);
  for (const auto& t : alone) CHECK(std::count(t.begin(), t.end(), 1) + std::count(t.begin(), t.end(), 3) == 2);
}

TEST_CASE("OBJ polygons written back as polygons with per-corner vt, normals kept") {
  const std::string source =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 2 0 0\nv 2 1 0\nvn 0 0 1\n"
      "f 1//1 2//1 3//1 4//1\nf 2 5 6 3\n";
  std::istringstream in(source);
  akvf::ObjPassthrough passthrough;
  const akvf::TriMesh mesh = akvf::read_obj(in, "quads.obj", nullptr, nullptr, &passthrough);
  REQUIRE(mesh.num_faces() == 4);
  Eigen::MatrixXd UV = mesh.V.leftCols(2);
  const auto path = (std::filesystem::temp_directory_path() / "akvf_quads_test.obj").string();
  akvf::write_obj_with_uv(path, mesh, UV, "", &passthrough);
  const std::string text = akvf::test::read_text(path);
  CHECK(text.find("f 1/1/1 2/2/1 3/3/1 4/4/1\nf 2/2 5/5 6/6 3/3\n") != std::string::npos);
  // A seam through the first quad (a corner of the diagonal with another
  // texture row in one of its two triangles): that quad goes out as triangles.
  Eigen::MatrixXd seam_uv(7, 2);
  seam_uv.topRows(6) = UV;
  seam_uv.row(6) << 9, 9;
  Eigen::MatrixXi seam_faces = mesh.F;
  for (int k = 0; k < 3; ++k)
    if ((mesh.F.row(1).array() == mesh.F(0, k)).any()) {
      seam_faces(0, k) = 6;
      break;
    }
  akvf::write_obj_with_uv(path, mesh, seam_uv, seam_faces, "", &passthrough);
  const std::string seamed = akvf::test::read_text(path);
  CHECK(seamed.find("f 2/2 5/5 6/6 3/3\n") != std::string::npos);
  CHECK(seamed.find("f 1/1/1 2/2/1 3/3/1 4/4/1") == std::string::npos);
  CHECK(seamed.find("/7/1 ") != std::string::npos);
  std::filesystem::remove(path);
}

TEST_CASE("OBJ: a line ending in a backslash goes on on the next, messages name the lines as the file has them") {
  const auto mesh = parse_mesh("v 0 0 0\nv 1 0 \\\n  0\nv 0 1 0\nf 1 2 \\\n 3\n", "continued.obj");
  CHECK(mesh.num_vertices() == 3);
  CHECK(mesh.num_faces() == 1);
  CHECK(mesh.V(1, 0) == 1.0);
  CHECK(obj_error("v 0 0 0\nv 1 0 \\\n 0\nv 0 1 0\nf 1 2 \\\n3\nf 1 2 x\n") ==
        "line 7 of bad.obj: face corner 'x' does not start with a vertex index (a whole number)");
}
