// PNG layouts: the image decodes (libpng), has the requested size, the
// triangles in their distortion colours on white, antialiased edges; the
// command line's --png and --png-size.
#include <doctest/doctest.h>
#include <png.h>

#include <cstdio>
#include <filesystem>

#include "akvf/internal/demo_mesh.h"
#include "cli/exit_codes.h"
#include "pictures/distortion_color.h"
#include "pictures/uv_png.h"
#include "tests/cli_support.h"

namespace fs = std::filesystem;

namespace {

struct Decoded {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
  const unsigned char* at(int x, int y) const { return rgb.data() + 3 * (std::size_t(y) * width + x); }
};

Decoded decode(const fs::path& path) {
  png_image image{};
  image.version = PNG_IMAGE_VERSION;
  REQUIRE(png_image_begin_read_from_file(&image, path.c_str()));
  image.format = PNG_FORMAT_RGB;
  Decoded out;
  out.width = static_cast<int>(image.width);
  out.height = static_cast<int>(image.height);
  out.rgb.resize(PNG_IMAGE_SIZE(image));
  REQUIRE(png_image_finish_read(&image, nullptr, out.rgb.data(), 0, nullptr));
  return out;
}

}  // namespace

TEST_CASE("a PNG layout: the requested size, each triangle in its distortion colour, white around, smooth edges") {
  const fs::path dir = akvf::test::scratch_dir("png_layout");
  Eigen::MatrixXd UV(4, 2);
  UV << 0, 0, 1, 0, 1, 1, 0, 1;
  Eigen::MatrixXi F(2, 3);
  F << 0, 1, 2, 0, 2, 3;
  Eigen::VectorXd excess(2);
  excess << 0.0, 50.0;  // white, dark red
  akvf::write_uv_png((dir / "square.png").string(), UV, F, excess, 200);
  const Decoded image = decode(dir / "square.png");
  CHECK(image.width == 200);
  CHECK(image.height == 200);
  const auto red = akvf::distortion_color(50.0);
  // Triangle (0,1,2) is below the diagonal (x > y in UV; y flipped in the
  // image); triangle (0,2,3) above it.
  const unsigned char* lower = image.at(150, 150);
  const unsigned char* upper = image.at(50, 50);
  CHECK(int(lower[0]) == 255);
  CHECK(int(lower[1]) == 255);
  CHECK(int(upper[0]) == red[0]);
  CHECK(int(upper[1]) == red[1]);
  CHECK(int(image.at(1, 1)[1]) == 255);  // the margin is white
  // On the diagonal the pixels mix the two colours (antialiasing).
  bool mixed = false;
  for (int x = 20; x < 180; ++x) {
    const int g = image.at(x, 199 - x)[1];
    mixed |= g > red[1] + 10 && g < 245;
  }
  CHECK(mixed);
  fs::remove_all(dir);
}

TEST_CASE("param --png writes the layout at --png-size, bad sizes and extensions are usage errors") {
  const fs::path dir = akvf::test::scratch_dir("png_cli");
  akvf::test::write_obj(dir / "bar.obj", akvf::bent_bar(21, 5));
  const auto ok = akvf::test::run_cli(
      {"param", (dir / "bar.obj").string(), "--png", (dir / "bar.png").string(), "--png-size", "300", "-q"});
  CHECK(ok.code == akvf::kExitOk);
  const Decoded image = decode(dir / "bar.png");
  CHECK(std::max(image.width, image.height) == 300);
  const auto bad = akvf::test::run_cli(
      {"param", (dir / "bar.obj").string(), "--png", (dir / "b.png").string(), "--png-size", "8", "-q"});
  CHECK(bad.code == akvf::kExitUsageError);
  CHECK(bad.err.find("--png-size must be an integer from 16 to 16384, found '8'") != std::string::npos);
  const auto jpg = akvf::test::run_cli({"param", (dir / "bar.obj").string(), "--png", (dir / "b.jpg").string(), "-q"});
  CHECK(jpg.code == akvf::kExitUsageError);
  CHECK(!fs::exists(dir / "b.png"));
  fs::remove_all(dir);
}
