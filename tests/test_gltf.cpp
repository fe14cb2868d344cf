// Display outputs. --out UV.glb: a binary glTF 2.0 whose structure a reader can follow: the
// header and chunk lengths, accessors within their views, the indices
// within the vertices, the PNG embedded, and the UVs of every corner.
#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <nlohmann/json.hpp>

#include "akvf/parameterize.h"
#include "framework/mesh/mesh_validation.h"
#include "io/checker_texture.h"
#include "io/gltf_writer.h"
#include "pictures/display_decimation.h"
#include "pictures/html_view.h"
#include "tests/cli_support.h"
#include "tests/test_support.h"

namespace fs = std::filesystem;

namespace {

std::uint32_t u32(const std::string& bytes, std::size_t at) {
  std::uint32_t value = 0;
  for (int i = 3; i >= 0; --i) value = value << 8 | static_cast<unsigned char>(bytes[at + i]);
  return value;
}

struct Glb {
  nlohmann::json json;
  std::string binary;
};

Glb read_glb(const fs::path& path) {
  const std::string bytes = akvf::test::read_text(path);
  REQUIRE(bytes.size() >= 28);
  CHECK(u32(bytes, 0) == 0x46546C67);
  CHECK(u32(bytes, 4) == 2);
  CHECK(u32(bytes, 8) == bytes.size());
  const std::uint32_t json_length = u32(bytes, 12);
  CHECK(u32(bytes, 16) == 0x4E4F534A);
  CHECK(json_length % 4 == 0);
  Glb glb;
  glb.json = nlohmann::json::parse(bytes.substr(20, json_length));
  const std::size_t bin = 20 + json_length;
  const std::uint32_t bin_length = u32(bytes, bin);
  CHECK(u32(bytes, bin + 4) == 0x004E4942);
  CHECK(bin + 8 + bin_length == bytes.size());
  glb.binary = bytes.substr(bin + 8, bin_length);
  CHECK(glb.json["buffers"][0]["byteLength"] == bin_length);
  return glb;
}

// The floats or uint32 of an accessor.
template <class T>
std::vector<T> accessor(const Glb& glb, int index, int components) {
  const auto& a = glb.json["accessors"][index];
  const auto& view = glb.json["bufferViews"][a["bufferView"].get<int>()];
  const std::size_t offset = view["byteOffset"], length = view["byteLength"], count = a["count"];
  REQUIRE(offset % 4 == 0);
  REQUIRE(length == count * components * 4);
  REQUIRE(offset + length <= glb.binary.size());
  std::vector<T> values(count * components);
  std::memcpy(values.data(), glb.binary.data() + offset, length);
  return values;
}

}  // namespace

TEST_CASE("param --out UV.glb writes a binary glTF with the mesh, per-corner UVs and the checkerboard") {
  const fs::path dir = akvf::test::scratch_dir("glb");
  const akvf::TriMesh torus = akvf::test::torus(10);
  akvf::test::write_obj(dir / "torus.obj", torus);
  const auto r = akvf::test::run_cli(
      {"param", (dir / "torus.obj").string(), "--cut", "auto", "--out", (dir / "uv.glb").string(), "--quiet"});
  REQUIRE(r.code == 0);
  const Glb glb = read_glb(dir / "uv.glb");
  CHECK(glb.json["asset"]["version"] == "2.0");
  const auto& primitive = glb.json["meshes"][0]["primitives"][0];
  CHECK(primitive["attributes"]["POSITION"] == 0);
  CHECK(primitive["attributes"]["TEXCOORD_0"] == 1);
  const std::vector<float> positions = accessor<float>(glb, 0, 3), uv = accessor<float>(glb, 1, 2);
  const std::vector<std::uint32_t> indices = accessor<std::uint32_t>(glb, 2, 1);
  const std::size_t vertices = positions.size() / 3;
  CHECK(vertices > static_cast<std::size_t>(torus.num_vertices()));  // seam vertices once per side
  REQUIRE(indices.size() == 3 * static_cast<std::size_t>(torus.num_faces()));
  int inverted = 0;
  for (int f = 0; f < torus.num_faces(); ++f) {
    float corner[3][2];
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t i = indices[3 * f + k];
      REQUIRE(i < vertices);
      for (int c = 0; c < 3; ++c) CHECK(positions[3 * i + c] == static_cast<float>(torus.V(torus.F(f, k), c)));
      corner[k][0] = uv[2 * i];
      corner[k][1] = 1 - uv[2 * i + 1];  // glTF's texture origin is top-left
      CHECK(corner[k][0] >= 0);
      CHECK(corner[k][0] <= 1);
    }
    const double det = (corner[1][0] - corner[0][0]) * (corner[2][1] - corner[0][1]) -
                       (corner[1][1] - corner[0][1]) * (corner[2][0] - corner[0][0]);
    inverted += !(det > 0);
  }
  CHECK(inverted == 0);
  // The embedded texture is a PNG.
  const auto& image_view = glb.json["bufferViews"][glb.json["images"][0]["bufferView"].get<int>()];
  CHECK(glb.json["images"][0]["mimeType"] == "image/png");
  CHECK(glb.binary.substr(image_view["byteOffset"].get<std::size_t>(), 8) == "\x89PNG\r\n\x1a\n");
  CHECK(glb.json["materials"][0]["pbrMetallicRoughness"]["baseColorTexture"]["index"] == 0);
  fs::remove_all(dir);
}

TEST_CASE("a coordinate beyond float range is refused for glTF, and no file is left") {
  const fs::path dir = akvf::test::scratch_dir("glb_range");
  akvf::TriMesh mesh = akvf::test::grid_disk(3, 3);
  mesh.V *= 1e300;
  const std::string message = akvf::test::error_message([&] {
    akvf::write_glb((dir / "x.glb").string(), mesh, mesh.V.leftCols(2) / 1e300, mesh.F, akvf::checker_image());
  });
  CHECK(message.find("does not fit glTF's 32-bit floats") != std::string::npos);
  CHECK_FALSE(fs::exists(dir / "x.glb"));
  fs::remove_all(dir);
}

TEST_CASE("display decimation: at most the asked faces, seam copies kept apart, every face a source face") {
  const akvf::TriMesh torus = akvf::test::torus(60);  // 7200 faces
  akvf::ParameterizeOptions options;
  options.cut = akvf::Cut::kAuto;
  options.max_iters = 5;
  const akvf::ParameterizeResult r = akvf::parameterize(torus.V, torus.F, options);
  const akvf::SeamSplitMesh split = akvf::split_at_seams(torus, r.uv, r.uv_faces);
  const akvf::DisplayMesh same = akvf::decimate_for_display(split, 100000);
  CHECK(same.mesh.mesh.F == split.mesh.F);
  const akvf::DisplayMesh small = akvf::decimate_for_display(split, 1000);
  CHECK(small.mesh.mesh.num_faces() <= 1000);
  CHECK(small.mesh.mesh.num_faces() >= 200);
  REQUIRE(static_cast<int>(small.source_face.size()) == small.mesh.mesh.num_faces());
  for (int f : small.source_face) CHECK((f >= 0 && f < torus.num_faces()));
  // UVs stay inside the map's bounds (means of its points), positions on the torus's bounds.
  CHECK((small.mesh.uv.colwise().minCoeff().array() >= r.uv.colwise().minCoeff().array() - 1e-12).all());
  CHECK((small.mesh.uv.colwise().maxCoeff().array() <= r.uv.colwise().maxCoeff().array() + 1e-12).all());
  CHECK(small.mesh.mesh.V.rowwise().norm().maxCoeff() <= 3 + 1e-12);
}

TEST_CASE("the view's data holds the seams: one segment per edge the cut opened, none without a cut") {
  if (!akvf::html_view_available()) return akvf::test::skip("three.js was not found at configure time");
  const fs::path dir = akvf::test::scratch_dir("view_seams");
  const akvf::TriMesh torus = akvf::test::torus(8);
  akvf::ParameterizeOptions options;
  options.cut = akvf::Cut::kAuto;
  options.min_coverage = 0;  // the cut's edges only
  const akvf::ParameterizeResult r = akvf::parameterize(torus.V, torus.F, options);
  const int cut_edges = akvf::prepare_disk_mesh(torus, "torus", true).cut_edges;
  REQUIRE(cut_edges > 0);
  const auto seams_text = [&](const Eigen::MatrixXd& uv, const Eigen::MatrixXi& uv_faces) {
    akvf::ViewContent content;
    content.mesh = torus;
    content.uv = uv;
    content.uv_faces = uv_faces;
    akvf::write_html_view((dir / "v.html").string(), content);
    const std::string page = akvf::test::read_text(dir / "v.html");
    const std::string open = "id=\"akvf-data\">";
    const std::size_t start = page.find(open) + open.size();
    return nlohmann::json::parse(page.substr(start, page.find("</script>", start) - start))["seams"].get<std::string>();
  };
  // 6 floats (24 bytes, 32 base64 characters) per segment.
  CHECK(seams_text(r.uv, r.uv_faces).size() == 32 * static_cast<std::size_t>(cut_edges));
  CHECK(seams_text(torus.V.leftCols(2), torus.F).empty());
  fs::remove_all(dir);
}

TEST_CASE("the view's data: any coordinate range, finite numbers, the distortion's mean at equal area") {
  if (!akvf::html_view_available()) return akvf::test::skip("three.js was not found at configure time");
  const fs::path dir = akvf::test::scratch_dir("view_data");
  for (const double scale : {1e-300, 1.0, 1e300}) {
    CAPTURE(scale);
    akvf::ViewContent content;
    content.mesh = akvf::test::bumpy_disk(6, 6);
    content.uv = content.mesh.V.leftCols(2) * 3;  // a map with distortion: bumps flattened
    content.mesh.V *= scale;
    content.uv_faces = content.mesh.F;
    content.title = "bumpy </script> & <b> <!--<script>";
    CHECK(akvf::write_html_view((dir / "v.html").string(), content) == content.mesh.num_faces());  // all shown
    const std::string page = akvf::test::read_text(dir / "v.html");
    CHECK(page.find("<title>bumpy &lt;/script&gt; &amp; &lt;b&gt; &lt;!--&lt;script&gt;</title>") != std::string::npos);
    const std::string open = "id=\"akvf-data\">";
    const std::size_t start = page.find(open) + open.size();
    CHECK(page.find("<!--", start) == std::string::npos);  // it would make the browser read past </script>
    const nlohmann::json data = nlohmann::json::parse(page.substr(start, page.find("</script>", start) - start));
    CHECK(data["title"] == "bumpy </script> & <b> <!--<script>");  // '<' written \u003c, the same JSON string
    CHECK(data["faces"] == content.mesh.num_faces());
    CHECK(data["degenerate_or_inverted"] == 0);
    CHECK(data["mean_distortion"].get<double>() > 4);
    CHECK(data["mean_distortion"].get<double>() < 4.5);
  }
  fs::remove_all(dir);
}
