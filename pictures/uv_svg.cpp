#include "pictures/uv_svg.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "framework/process/output_file.h"
#include "io/text_utilities.h"
#include "pictures/distortion_color.h"
#include "pictures/layout.h"

namespace akvf {

namespace {

std::string color_for(double excess) {
  const auto rgb = distortion_color(excess);
  char buffer[8];
  std::snprintf(buffer, sizeof buffer, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
  return buffer;
}

}  // namespace

void write_uv_svg(const std::string& path, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F,
                  const Eigen::VectorXd& distortion, const std::string& title) {
  const Eigen::RowVector2d lo = UV.colwise().minCoeff(), hi = UV.colwise().maxCoeff();
  const double extent = std::max((hi - lo).maxCoeff(), 1e-300);
  const double size = 800, margin = 20;
  const double scale = (size - 2 * margin) / extent;
  const double width = (hi - lo).x() * scale + 2 * margin, height = (hi - lo).y() * scale + 2 * margin + 24;
  // y grows downwards in SVG: flip so the picture has the UV orientation.
  auto px = [&](int v) { return margin + (UV(v, 0) - lo.x()) * scale; };
  auto py = [&](int v) { return height - margin - (UV(v, 1) - lo.y()) * scale; };
  write_file_atomically(path, [&](std::ostream& out) {
    char buffer[160];
    out << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << width << "\" height=\"" << height
        << "\" viewBox=\"0 0 " << width << ' ' << height << "\">\n";
    out << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
    out << "<text x=\"" << margin << "\" y=\"18\" font-family=\"sans-serif\" font-size=\"14\">" << xml_escape(title)
        << "</text>\n";
    out << "<g stroke=\"#333\" stroke-width=\"0.3\" stroke-linejoin=\"round\">\n";
    for (int f = 0; f < F.rows(); ++f) {
      std::snprintf(buffer, sizeof buffer, "<path d=\"M%.1f %.1fL%.1f %.1fL%.1f %.1fZ\" fill=\"", px(F(f, 0)),
                    py(F(f, 0)), px(F(f, 1)), py(F(f, 1)), px(F(f, 2)), py(F(f, 2)));
      out << buffer << color_for(distortion[f]) << "\"/>\n";
    }
    out << "</g>\n</svg>\n";
  });
}

void write_layout_svg(const std::string& path, const ParamSetup& setup, const Eigen::VectorXd& x,
                      const std::string& title) {
  const Layout layout = layout_of(setup, x);
  write_uv_svg(path, layout.uv, layout.F, layout.excess, title);
}

}  // namespace akvf
