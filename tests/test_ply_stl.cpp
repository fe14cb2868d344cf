// PLY (ASCII, binary little and big endian) and STL (ASCII, binary, welded)
// readers: the same mesh from every encoding, the start map a PLY carries,
// and one test per malformed input naming the file, the line or byte, and
// the problem.
#include <doctest/doctest.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <sstream>

#include "akvf/mesh_io.h"
#include "akvf/parameterize.h"
#include "io/ply_reader.h"
#include "io/stl_reader.h"
#include "tests/cli_support.h"
#include "tests/test_support.h"

using akvf::test::error_message;

namespace {

// Appends `value` as `bytes` bytes in the given byte order.
template <class T>
void put(std::string* out, T value, bool big_endian) {
  char bytes[sizeof(T)];
  std::memcpy(bytes, &value, sizeof(T));
  if (big_endian) std::reverse(bytes, bytes + sizeof(T));
  out->append(bytes, sizeof(T));
}

// The mesh as PLY: x y z (double, or float when `single`), u v if given,
// faces as uchar-counted int lists, and an extra vertex property and element.
std::string ply(const akvf::TriMesh& mesh, const std::string& format, const Eigen::MatrixXd& uv = {}) {
  const bool binary = format != "ascii", big = format == "binary_big_endian";
  std::ostringstream header;
  header << "ply\nformat " << format << " 1.0\ncomment made by test_ply_stl\nelement vertex " << mesh.num_vertices()
         << "\nproperty double x\nproperty double y\nproperty double z\nproperty uchar red\n";
  if (uv.rows() > 0) header << "property float s\nproperty float t\n";
  header << "element face " << mesh.num_faces() << "\nproperty list uchar int vertex_indices\n"
         << "element edge 1\nproperty int vertex1\nproperty int vertex2\nend_header\n";
  std::string out = header.str();
  std::ostringstream text;
  text << std::setprecision(17);
  for (int v = 0; v < mesh.num_vertices(); ++v) {
    if (binary) {
      for (int k = 0; k < 3; ++k) put<double>(&out, mesh.V(v, k), big);
      put<std::uint8_t>(&out, 200, big);
      if (uv.rows() > 0)
        for (int k = 0; k < 2; ++k) put<float>(&out, static_cast<float>(uv(v, k)), big);
    } else {
      text << mesh.V(v, 0) << ' ' << mesh.V(v, 1) << ' ' << mesh.V(v, 2) << " 200";
      if (uv.rows() > 0) text << ' ' << static_cast<float>(uv(v, 0)) << ' ' << static_cast<float>(uv(v, 1));
      text << '\n';
    }
  }
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (binary) {
      put<std::uint8_t>(&out, 3, big);
      for (int k = 0; k < 3; ++k) put<std::int32_t>(&out, mesh.F(f, k), big);
    } else {
      text << "3 " << mesh.F(f, 0) << ' ' << mesh.F(f, 1) << ' ' << mesh.F(f, 2) << '\n';
    }
  }
  if (binary) {
    put<std::int32_t>(&out, 0, big);
    put<std::int32_t>(&out, 1, big);
  } else {
    text << "0 1\n";
  }
  return out + text.str();
}

std::string stl(const akvf::TriMesh& mesh, bool binary) {
  std::string out;
  std::ostringstream text;
  text << std::setprecision(17) << "solid test\n";
  if (binary) {
    out.assign(80, ' ');
    out.replace(0, 5, "solid");  // many binary files begin so too
    put<std::uint32_t>(&out, static_cast<std::uint32_t>(mesh.num_faces()), false);
  }
  for (int f = 0; f < mesh.num_faces(); ++f) {
    if (binary) {
      for (int k = 0; k < 3; ++k) put<float>(&out, 0.0f, false);
      for (int c = 0; c < 3; ++c)
        for (int k = 0; k < 3; ++k) put<float>(&out, static_cast<float>(mesh.V(mesh.F(f, c), k)), false);
      put<std::uint16_t>(&out, 0, false);
    } else {
      text << "  facet normal 0 0 1\n    outer loop\n";
      for (int c = 0; c < 3; ++c)
        text << "      vertex " << mesh.V(mesh.F(f, c), 0) << ' ' << mesh.V(mesh.F(f, c), 1) << ' '
             << mesh.V(mesh.F(f, c), 2) << '\n';
      text << "    endloop\n  endfacet\n";
    }
  }
  text << "endsolid test\n";
  return binary ? out : text.str();
}

akvf::TriMesh read_ply_text(const std::string& data, Eigen::MatrixXd* uv = nullptr) {
  std::istringstream in(data);
  return akvf::read_ply(in, "m.ply", uv);
}
akvf::TriMesh read_stl_text(const std::string& data) {
  std::istringstream in(data);
  return akvf::read_stl(in, "m.stl");
}
std::string ply_error(const std::string& data) {
  return error_message([&] { read_ply_text(data); });
}
std::string stl_error(const std::string& data) {
  return error_message([&] { read_stl_text(data); });
}

}  // namespace

TEST_CASE("PLY: ASCII, binary little and big endian give the same mesh, extra properties and elements are skipped") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(6, 5);
  for (const char* format : {"ascii", "binary_little_endian", "binary_big_endian"}) {
    CAPTURE(format);
    const akvf::TriMesh read = read_ply_text(ply(mesh, format));
    CHECK(read.V == mesh.V);
    CHECK(read.F == mesh.F);
    CHECK(read.index_base == 0);
  }
}

TEST_CASE("PLY: s,t (or u,v, texture_u,texture_v) are read as the start map") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(6, 5);
  const Eigen::MatrixXd uv = mesh.V.leftCols(2) * 0.5;
  for (const char* format : {"ascii", "binary_big_endian"}) {
    Eigen::MatrixXd read_uv;
    read_ply_text(ply(mesh, format, uv), &read_uv);
    REQUIRE(read_uv.rows() == mesh.num_vertices());
    CHECK((read_uv - uv).cwiseAbs().maxCoeff() < 1e-7);  // stored as float
  }
  Eigen::MatrixXd none;
  read_ply_text(ply(mesh, "ascii"), &none);
  CHECK(none.rows() == 0);
}

TEST_CASE("PLY: malformed headers and bodies name the line or byte and the problem") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(3, 3);
  const std::string good = ply(mesh, "ascii"), binary = ply(mesh, "binary_little_endian");
  CHECK(ply_error("plx\n") == "line 1 of m.ply: not a PLY file (the first line must be 'ply')");
  CHECK(ply_error("ply\nformat ascii 1.0\nelement vertex 3\n") ==
        "line 3 of m.ply: the header has no 'end_header' line");
  CHECK(ply_error("ply\nformat utf8 1.0\nend_header\n") == "line 2 of m.ply: unknown PLY format 'utf8'");
  CHECK(
      ply_error("ply\nformat ascii 1.0\nelement vertex -4\nend_header\n").find("line 3 of m.ply: element count '-4'") ==
      0);
  CHECK(ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty quad x\nend_header\n") ==
        "line 4 of m.ply: unknown property type 'quad'");
  CHECK(ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nproperty float z\n"
                  "end_header\n0 0 0\n") ==
        "line 7 of m.ply: the header declares no 'face' element (a point cloud is "
        "not a mesh)");
  CHECK(ply_error("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nelement face 1\n"
                  "property list uchar int vertex_indices\nend_header\n") ==
        "line 3 of m.ply: the vertex element has no 'z' property");
  // A quad, an index out of range, a short row, a stray row (ASCII).
  std::string quad = good;
  quad.replace(quad.find("\n3 "), 3, "\n4 9 ");
  CHECK(ply_error(quad).find("face 0: vertex index 9 out of range") != std::string::npos);  // a quad is read
  std::string two = good;
  two.replace(two.find("\n3 "), 3, "\n2 ");
  CHECK(ply_error(two).find("face 0 has 2 corners; a face needs at least three") != std::string::npos);
  std::string out_of_range = good;
  out_of_range.replace(out_of_range.find("\n3 ") + 3, 1, "99");
  CHECK(ply_error(out_of_range).find("face 0: vertex index 99") != std::string::npos);
  std::string huge_index = good;
  huge_index.replace(huge_index.find("\n3 ") + 3, 1, "99999999999");
  CHECK(ply_error(huge_index)
            .find("'99999999999' is not an integer of the declared type (item 0 of property "
                  "'vertex_indices' of face 0)") != std::string::npos);
  CHECK(ply_error(good + "1 2\n").find("more rows than the header's element counts declare") != std::string::npos);
  const std::size_t blue = good.find(" 200\n");
  REQUIRE(blue != std::string::npos);
  const std::string short_row = good.substr(0, blue) + "\n" + good.substr(blue + 5);
  CHECK(ply_error(short_row).find("the line ends before property 'red' of vertex 0") != std::string::npos);
  // Binary: truncated, or counts far larger than the file (refused before allocating).
  CHECK(ply_error(binary.substr(0, binary.size() - 3)).find("m.ply: byte ") == 0);
  CHECK(ply_error(binary.substr(0, binary.size() - 3)).find("(truncated?)") != std::string::npos);
  std::string huge = binary;
  huge.replace(huge.find("element face 8"), 14, "element face 2000000000");
  CHECK(ply_error(huge).find("the header declares at least") != std::string::npos);
  CHECK(ply_error(binary + "xx").find("2 bytes follow the last element") != std::string::npos);
}

TEST_CASE("STL: ASCII and binary are welded back into the indexed mesh") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(7, 6);
  for (const bool binary : {false, true}) {
    CAPTURE(binary);
    const akvf::TriMesh read = read_stl_text(stl(mesh, binary));
    REQUIRE(read.num_vertices() == mesh.num_vertices());
    REQUIRE(read.num_faces() == mesh.num_faces());
    // Vertices by first appearance: map them back through the faces.
    for (int f = 0; f < mesh.num_faces(); ++f)
      for (int c = 0; c < 3; ++c)
        CHECK((read.V.row(read.F(f, c)) - mesh.V.row(mesh.F(f, c))).norm() <= (binary ? 1e-6 : 0.0));
  }
}

TEST_CASE("STL: corners within the weld tolerance are one vertex, farther ones are not") {
  const std::string two_facets_far =
      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
      "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 1 0 0\nvertex 1 1 0\n"
      "vertex 0 1.000001 0\nendloop\nendfacet\nendsolid s\n";
  CHECK(read_stl_text(two_facets_far).num_vertices() == 5);  // 1e-6 apart > 4.8e-7 x sqrt(2)
  std::string near = two_facets_far;
  near.replace(near.find("0 1.000001 0"), 12, "0 1.0000001 0");
  CHECK(read_stl_text(near).num_vertices() == 4);  // 1e-7 apart: within the tolerance
}

TEST_CASE("STL: a plate thinner than the diagonal's ulps keeps its two sides (the tolerance follows the facets)") {
  // A 10 x 10 plate's top facet and a side wall 1e-6 high: the diagonal's
  // tolerance (4.8e-7 x 14) would weld across, a tenth of the shortest edge
  // does not.
  const std::string plate =
      "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0.000001\nvertex 10 0 0.000001\nvertex 0 10 0.000001\n"
      "endloop\nendfacet\nfacet normal 1 0 0\nouter loop\nvertex 0 0 0\nvertex 10 0 0\nvertex 10 0 0.000001\n"
      "endloop\nendfacet\nendsolid s\n";
  const akvf::TriMesh read = read_stl_text(plate);
  CHECK(read.num_vertices() == 5);
  CHECK(read.num_faces() == 2);
}

TEST_CASE("STL: keywords in any case, as some writers spell them") {
  std::string upper =
      "SOLID S\nFACET NORMAL 0 0 1\nOUTER LOOP\nVERTEX 0 0 0\nVERTEX 1 0 0\nVERTEX 0 1 0\n"
      "ENDLOOP\nENDFACET\nENDSOLID S\n";
  const akvf::TriMesh read = read_stl_text(upper);
  CHECK(read.num_vertices() == 3);
  CHECK(read.num_faces() == 1);
}

TEST_CASE("STL: malformed files name the line or the problem") {
  CHECK(stl_error("sold\n").find("m.stl: too short for an STL file") == 0);
  CHECK(stl_error("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0\n") ==
        "line 4 of m.stl: a vertex line needs three coordinates");
  CHECK(stl_error("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\nvertex 1 1 0\n")
            .find("line 7 of m.stl: a facet with more than 3 vertices") == 0);
  CHECK(stl_error("solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n") ==
        "line 4 of m.stl: the file ends where 'vertex' was expected");
  CHECK(stl_error("solid s\nendsolid s\n") == "m.stl: the file has no facets");
  CHECK(stl_error(std::string(100, 'x')).find("m.stl: neither ASCII STL") == 0);
}

TEST_CASE("a disk mesh from PLY or STL parameterizes as from OBJ") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(9, 8);
  const double reference = akvf::parameterize(mesh.V, mesh.F).energy();
  const akvf::TriMesh from_ply = read_ply_text(ply(mesh, "binary_little_endian"));
  CHECK(akvf::parameterize(from_ply.V, from_ply.F).energy() == reference);
  const akvf::TriMesh from_stl = read_stl_text(stl(mesh, false));
  CHECK(akvf::parameterize(from_stl.V, from_stl.F).energy() == doctest::Approx(reference).epsilon(1e-9));
}

TEST_CASE("PLY output: binary with per-vertex s, t reads back to the same bits") {
  const akvf::TriMesh mesh = akvf::test::bumpy_disk(6, 5);
  const Eigen::MatrixXd uv = mesh.V.leftCols(2) * 0.37 + Eigen::MatrixXd::Constant(mesh.num_vertices(), 2, 1.0 / 3);
  const std::filesystem::path path = akvf::test::scratch_dir("ply_out") / "uv.ply";
  akvf::write_ply_with_uv(path.string(), mesh, uv);
  std::ifstream in(path, std::ios::binary);
  Eigen::MatrixXd read_uv;
  const akvf::TriMesh read = akvf::read_ply(in, path.string(), &read_uv);
  CHECK(read.V == mesh.V);
  CHECK(read.F == mesh.F);
  CHECK(read_uv == uv);
  std::filesystem::remove_all(path.parent_path());
}

TEST_CASE("PLY output after a cut: per-corner texcoord reads back as the mesh's per-corner texture") {
  const akvf::TriMesh torus = akvf::test::torus(8);
  akvf::ParameterizeOptions options;
  options.cut = akvf::Cut::kAuto;
  options.max_iters = 20;
  const akvf::ParameterizeResult r = akvf::parameterize(torus.V, torus.F, options);
  const std::filesystem::path dir = akvf::test::scratch_dir("ply_corners");
  akvf::write_ply_with_uv((dir / "uv.ply").string(), torus, r.uv, r.uv_faces);
  akvf::MeshTexture texture;
  const akvf::TriMesh read = akvf::read_triangle_mesh((dir / "uv.ply").string(), nullptr, &texture);
  CHECK(read.V == torus.V);
  CHECK(read.F == torus.F);
  REQUIRE(texture.corner.rows() == torus.num_faces());
  for (int f = 0; f < torus.num_faces(); ++f)
    for (int k = 0; k < 3; ++k)
      CHECK((texture.uv.row(texture.corner(f, k)) - r.uv.row(r.uv_faces(f, k))).cwiseAbs().maxCoeff() <=
            1e-6 * r.uv.cwiseAbs().maxCoeff());  // stored as float
  std::filesystem::remove_all(dir);
  const std::string bad =
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n"
      "0 0 0\n1 0 0\n0 1 0\n3 0 1 2 4 0 0 1 0\n";
  CHECK(ply_error(bad).find("face 0 has 4 texcoord values; its 3 corners need 6 (u, v per corner)") !=
        std::string::npos);
}

TEST_CASE("PLY: a quad with per-corner texcoord is triangulated, each triangle corner keeps its own u, v") {
  const std::string quad =
      "ply\nformat ascii 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nproperty list uchar float texcoord\nend_header\n"
      "0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3 8 0 0 0.5 0 0.5 0.5 0 0.5\n";
  std::istringstream in(quad);
  Eigen::MatrixXd uv, corner_uv;
  akvf::Warnings warnings;
  const akvf::TriMesh mesh = akvf::read_ply(in, "q.ply", &uv, &corner_uv, &warnings);
  REQUIRE(mesh.num_faces() == 2);
  REQUIRE(corner_uv.rows() == 6);
  CHECK(warnings.size() == 1);
  for (int f = 0; f < 2; ++f)
    for (int k = 0; k < 3; ++k)  // u, v = half of x, y here
      CHECK((corner_uv.row(3 * f + k) - 0.5 * mesh.V.row(mesh.F(f, k)).head<2>()).norm() == 0);
}

TEST_CASE("PLY: an element with rows but no property is refused at its header line (nothing to read per row)") {
  CHECK(ply_error("ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                  "element junk 1996345774\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n"
                  "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n") ==
        "line 7 of m.ply: element 'junk' declares 1996345774 rows but no property");
}
