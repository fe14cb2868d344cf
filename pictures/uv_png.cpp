#include "pictures/uv_png.h"

#include <algorithm>
#include <cmath>

#include "akvf/error.h"
#include "io/png_image.h"
#include "pictures/distortion_color.h"
#include "pictures/layout.h"

namespace akvf {

namespace {

constexpr int kSamples = 4;  // per pixel and axis

}  // namespace

void write_uv_png(const std::string& path, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F,
                  const Eigen::VectorXd& distortion, int size) {
  if (size < 16 || size > 16384)
    throw OptionsError("the PNG size must be 16 to 16384 pixels, found " + std::to_string(size));
  const Eigen::RowVector2d lo = UV.colwise().minCoeff(), hi = UV.colwise().maxCoeff();
  const double extent = std::max((hi - lo).maxCoeff(), 1e-300);
  const int margin = std::max(2, size / 50);
  const double scale = (size - 2 * margin) / extent;
  const int width = static_cast<int>(std::ceil((hi - lo).x() * scale)) + 2 * margin;
  const int height = static_cast<int>(std::ceil((hi - lo).y() * scale)) + 2 * margin;
  // Coverage-weighted colour sums per pixel, from kSamples^2 samples each.
  std::vector<float> sum(3 * std::size_t(width) * height, 0.0f);
  std::vector<unsigned short> hits(std::size_t(width) * height, 0);
  const double sub = 1.0 / kSamples;
  // Sample positions in pixel units: x to the right, y downwards (flipped so
  // the picture has the UV orientation).
  const auto px = [&](int v) { return margin + (UV(v, 0) - lo.x()) * scale; };
  const auto py = [&](int v) { return height - margin - (UV(v, 1) - lo.y()) * scale; };
  for (int f = 0; f < F.rows(); ++f) {
    const double x0 = px(F(f, 0)), y0 = py(F(f, 0)), x1 = px(F(f, 1)), y1 = py(F(f, 1)), x2 = px(F(f, 2)),
                 y2 = py(F(f, 2));
    const double area = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
    if (!(std::abs(area) > 0)) continue;
    const auto color = distortion_color(distortion[f]);
    // Samples at (i + 0.5) / kSamples in the triangle's bounding box.
    const int sx0 = std::max(0, static_cast<int>(std::floor(std::min({x0, x1, x2}) * kSamples)));
    const int sx1 = std::min(width * kSamples - 1, static_cast<int>(std::ceil(std::max({x0, x1, x2}) * kSamples)));
    const int sy0 = std::max(0, static_cast<int>(std::floor(std::min({y0, y1, y2}) * kSamples)));
    const int sy1 = std::min(height * kSamples - 1, static_cast<int>(std::ceil(std::max({y0, y1, y2}) * kSamples)));
    for (int sy = sy0; sy <= sy1; ++sy)
      for (int sx = sx0; sx <= sx1; ++sx) {
        const double x = (sx + 0.5) * sub, y = (sy + 0.5) * sub;
        // Barycentric signs, orientation-independent.
        const double w0 = ((x1 - x) * (y2 - y) - (x2 - x) * (y1 - y)) / area;
        const double w1 = ((x2 - x) * (y0 - y) - (x0 - x) * (y2 - y)) / area;
        const double w2 = 1 - w0 - w1;
        if (w0 < 0 || w1 < 0 || w2 < 0) continue;
        const std::size_t pixel = std::size_t(sy / kSamples) * width + sx / kSamples;
        if (hits[pixel] >= kSamples * kSamples) continue;  // shared edges: a sample counts once per pixel at most
        ++hits[pixel];
        for (int c = 0; c < 3; ++c) sum[3 * pixel + c] += color[c];
      }
  }
  RgbImage image(width, height);
  for (std::size_t pixel = 0; pixel < hits.size(); ++pixel) {
    const float covered = static_cast<float>(hits[pixel]) / (kSamples * kSamples);
    for (int c = 0; c < 3; ++c)
      image.rgb[3 * pixel + c] =
          static_cast<unsigned char>(std::lround(sum[3 * pixel + c] / (kSamples * kSamples) + 255.0f * (1 - covered)));
  }
  write_png(path, image);
}

void write_layout_png(const std::string& path, const ParamSetup& setup, const Eigen::VectorXd& x, int size) {
  const Layout layout = layout_of(setup, x);
  write_uv_png(path, layout.uv, layout.F, layout.excess, size);
}

}  // namespace akvf
