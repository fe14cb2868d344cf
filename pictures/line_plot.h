#pragma once
// Line plots as standalone SVG (no plotting dependency): one polyline per
// series, linear or log10 axes with labelled ticks, a legend. Used for the
// energy-against-iterations and energy-against-seconds figures.
#include <string>
#include <vector>

namespace akvf {

struct PlotSeries {
  std::string label;
  std::vector<double> x, y;  // same length; points with a non-positive value on a log axis are skipped
};

struct PlotSpec {
  std::string title, x_label, y_label;
  bool log_x = false, log_y = false;
};

// The SVG text. Throws OptionsError if no series has a point to draw.
std::string line_plot_svg(const PlotSpec& spec, const std::vector<PlotSeries>& series);

}  // namespace akvf
