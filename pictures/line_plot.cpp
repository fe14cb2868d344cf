#include "pictures/line_plot.h"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>

#include "akvf/error.h"
#include "io/text_utilities.h"

namespace akvf {

namespace {

constexpr double kWidth = 640, kHeight = 420;
constexpr double kLeft = 80, kRight = 170, kTop = 40, kBottom = 55;  // margins; the legend sits on the right
const char* kColors[] = {"#1f77b4", "#d62728", "#2ca02c", "#ff7f0e", "#9467bd", "#8c564b", "#e377c2", "#17becf"};

// One axis: data value -> pixel, and its ticks.
struct Axis {
  bool log = false;
  double lo = 0, hi = 1;  // in axis units (log10 when log)
  double pixel_lo = 0, pixel_hi = 1;

  double to_unit(double v) const { return log ? std::log10(v) : v; }
  double pixel(double v) const { return pixel_lo + (to_unit(v) - lo) / (hi - lo) * (pixel_hi - pixel_lo); }

  // Tick values in data units: powers of ten on a log axis, 1-2-5 steps otherwise.
  std::vector<double> ticks() const {
    std::vector<double> values;
    if (log) {
      for (double e = std::ceil(lo - 1e-9); e <= hi + 1e-9; ++e) values.push_back(std::pow(10.0, e));
      return values;
    }
    const double raw = (hi - lo) / 6, magnitude = std::pow(10.0, std::floor(std::log10(raw)));
    double step = magnitude;
    for (double m : {1.0, 2.0, 5.0, 10.0})
      if (m * magnitude >= raw) {
        step = m * magnitude;
        break;
      }
    for (double v = std::ceil(lo / step) * step; v <= hi + 1e-9 * step; v += step) values.push_back(v);
    return values;
  }
};

bool usable(double v, bool log) { return std::isfinite(v) && (!log || v > 0); }

Axis make_axis(const std::vector<PlotSeries>& series, bool use_x, bool log, double pixel_lo, double pixel_hi) {
  Axis axis;
  axis.log = log;
  axis.pixel_lo = pixel_lo;
  axis.pixel_hi = pixel_hi;
  double lo = std::numeric_limits<double>::infinity(), hi = -lo;
  for (const PlotSeries& s : series)
    for (std::size_t i = 0; i < s.x.size(); ++i) {
      if (!usable(s.x[i], use_x ? log : false) || !usable(s.y[i], use_x ? false : log)) continue;
      const double v = axis.to_unit(use_x ? s.x[i] : s.y[i]);
      lo = std::min(lo, v);
      hi = std::max(hi, v);
    }
  if (!(lo <= hi))
    throw OptionsError("nothing to plot: no series has a point with finite (and, on a log axis, positive) values");
  if (log) {
    lo = std::floor(lo);
    hi = std::max(std::ceil(hi), lo + 1);
  } else if (lo >= 0 && lo < 0.5 * hi) {
    lo = 0;  // non-negative data (iterations, seconds) starts at the origin
  } else if (hi - lo < 1e-12 * std::max(1.0, std::abs(hi))) {
    lo -= 1;
    hi += 1;
  }
  axis.lo = lo;
  axis.hi = hi;
  return axis;
}

std::string format_tick(double v, bool log) {
  std::ostringstream text;
  if (log) {
    text << "1e" << static_cast<int>(std::lround(std::log10(v)));
  } else {
    text << std::setprecision(6) << (std::abs(v) < 1e-12 ? 0.0 : v);
  }
  return text.str();
}

}  // namespace

std::string line_plot_svg(const PlotSpec& spec, const std::vector<PlotSeries>& series) {
  const Axis x = make_axis(series, true, spec.log_x, kLeft, kWidth - kRight);
  const Axis y = make_axis(series, false, spec.log_y, kHeight - kBottom, kTop);
  std::ostringstream svg;
  svg << std::setprecision(6);
  svg << "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"" << kWidth << "\" height=\"" << kHeight
      << "\" font-family=\"sans-serif\" font-size=\"12\">\n";
  svg << "<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n";
  svg << "<text x=\"" << (kLeft + kWidth - kRight) / 2 << "\" y=\"22\" text-anchor=\"middle\" font-size=\"14\">"
      << xml_escape(spec.title) << "</text>\n";
  // Grid and ticks.
  for (double t : x.ticks()) {
    const double px = x.pixel(t);
    svg << "<line x1=\"" << px << "\" y1=\"" << kTop << "\" x2=\"" << px << "\" y2=\"" << kHeight - kBottom
        << "\" stroke=\"#e0e0e0\"/>\n<text x=\"" << px << "\" y=\"" << kHeight - kBottom + 16
        << "\" text-anchor=\"middle\">" << format_tick(t, x.log) << "</text>\n";
  }
  for (double t : y.ticks()) {
    const double py = y.pixel(t);
    svg << "<line x1=\"" << kLeft << "\" y1=\"" << py << "\" x2=\"" << kWidth - kRight << "\" y2=\"" << py
        << "\" stroke=\"#e0e0e0\"/>\n<text x=\"" << kLeft - 6 << "\" y=\"" << py + 4 << "\" text-anchor=\"end\">"
        << format_tick(t, y.log) << "</text>\n";
  }
  svg << "<rect x=\"" << kLeft << "\" y=\"" << kTop << "\" width=\"" << kWidth - kLeft - kRight << "\" height=\""
      << kHeight - kTop - kBottom << "\" fill=\"none\" stroke=\"black\"/>\n";
  svg << "<text x=\"" << (kLeft + kWidth - kRight) / 2 << "\" y=\"" << kHeight - 12 << "\" text-anchor=\"middle\">"
      << xml_escape(spec.x_label) << "</text>\n";
  svg << "<text transform=\"translate(18," << (kTop + kHeight - kBottom) / 2
      << ") rotate(-90)\" text-anchor=\"middle\">" << xml_escape(spec.y_label) << "</text>\n";
  // Series and legend.
  for (std::size_t s = 0; s < series.size(); ++s) {
    const char* color = kColors[s % std::size(kColors)];
    svg << "<polyline fill=\"none\" stroke=\"" << color << "\" stroke-width=\"1.8\" points=\"";
    for (std::size_t i = 0; i < series[s].x.size(); ++i)
      if (usable(series[s].x[i], x.log) && usable(series[s].y[i], y.log))
        svg << x.pixel(series[s].x[i]) << ',' << y.pixel(series[s].y[i]) << ' ';
    svg << "\"/>\n";
    const double ly = kTop + 10 + 20 * static_cast<double>(s);
    svg << "<line x1=\"" << kWidth - kRight + 12 << "\" y1=\"" << ly << "\" x2=\"" << kWidth - kRight + 36 << "\" y2=\""
        << ly << "\" stroke=\"" << color << "\" stroke-width=\"2.5\"/>\n<text x=\"" << kWidth - kRight + 42 << "\" y=\""
        << ly + 4 << "\">" << xml_escape(series[s].label) << "</text>\n";
  }
  svg << "</svg>\n";
  return svg.str();
}

}  // namespace akvf
