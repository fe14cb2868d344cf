#include "io/checker_texture.h"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include "framework/process/output_file.h"
#include "io/png_image.h"

namespace akvf {

TextureFiles texture_files_for(const std::string& obj_path) {
  const std::filesystem::path obj(obj_path);
  // White space becomes '_': readers split `mtllib` and `map_Kd` lines on it.
  std::string stem = obj.stem().string();
  std::replace_if(
      stem.begin(), stem.end(), [](unsigned char c) { return std::isspace(c) != 0; }, '_');
  TextureFiles files;
  files.mtl_name = stem + ".mtl";
  files.png_name = stem + "_checker.png";
  files.mtl = (obj.parent_path() / files.mtl_name).string();
  files.png = (obj.parent_path() / files.png_name).string();
  return files;
}

RgbImage checker_image() {
  constexpr int kSize = 1024, kSquares = 16;
  RgbImage image(kSize, kSize);
  for (int y = 0; y < kSize; ++y)
    for (int x = 0; x < kSize; ++x) {
      const bool dark = ((x * kSquares / kSize) + (y * kSquares / kSize)) % 2 == 1;
      unsigned char* p = image.pixel(x, y);
      p[0] = dark ? 40 : 235;
      p[1] = dark ? 40 : 235;
      p[2] = dark ? 40 : 235;
    }
  return image;
}

void write_checker_texture(const TextureFiles& files) {
  write_png(files.png, checker_image());
  write_file_atomically(files.mtl, [&](std::ostream& out) {
    out << "# written by akvf: the checkerboard of the parameterization\n"
        << "newmtl checker\nKa 1 1 1\nKd 1 1 1\nKs 0 0 0\nillum 1\nmap_Kd " << files.png_name << '\n';
  });
}

double unit_square_scale(const Eigen::MatrixXd& UV) {
  const Eigen::RowVector2d lo = UV.colwise().minCoeff(), hi = UV.colwise().maxCoeff();
  return 1 / std::max((hi - lo).maxCoeff(), 1e-300);
}

Eigen::MatrixXd unit_square_uv(const Eigen::MatrixXd& UV) {
  const Eigen::RowVector2d lo = UV.colwise().minCoeff();
  return (UV.rowwise() - lo) * unit_square_scale(UV);
}

}  // namespace akvf
