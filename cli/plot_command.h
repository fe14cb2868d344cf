#pragma once
// The `akvf plot` command: SVG line plots of trace CSV files (one line per
// trace), e.g. energy against iterations or seconds on a log scale.
#include <ostream>
#include <string>
#include <vector>

namespace akvf {

int plot_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err);

}  // namespace akvf
