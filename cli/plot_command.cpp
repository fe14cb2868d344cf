#include "cli/plot_command.h"

#include "akvf/error.h"
#include "cli/command_line.h"
#include "cli/exit_codes.h"
#include "cli/file_arguments.h"
#include "experiments/report/trace_csv.h"
#include "framework/process/output_file.h"
#include "pictures/line_plot.h"

namespace akvf {

int plot_command(const std::vector<std::string>& args, std::ostream& out, std::ostream&) {
  CommandLine cl(
      "akvf plot TRACE.csv[=LABEL]... --out FIGURE.svg [options]\n\n"
      "Draws one line per trace file (written by --trace): a column against iterations or seconds.\n"
      "LABEL names the line in the legend (default: the file name).",
      {
          {"out", "FIGURE.svg", "the SVG to write (required)"},
          {"x", "COLUMN", "horizontal axis: iter (default) or seconds"},
          {"y", "COLUMN", "vertical axis: energy (default), grad_norm, or any numeric trace column"},
          {"minus", "VALUE", "plot y - VALUE (e.g. the energy's lower bound)"},
          {"log-y", "on|off", "log10 vertical axis (default on)"},
          {"title", "TEXT", "title above the plot"},
          {"help", "", "show this help"},
      });
  cl.parse(args);
  if (cl.has("help")) {
    out << cl.help();
    return kExitOk;
  }
  if (cl.positional().empty()) throw OptionsError("expected at least one trace file (see --help)");
  if (!cl.has("out")) throw OptionsError("option --out is required");
  const std::string out_path = cl.text("out", ""), x_name = cl.text("x", "iter"), y_name = cl.text("y", "energy");
  const std::string log_y = cl.text("log-y", "on");
  if (log_y != "on" && log_y != "off") throw OptionsError("option --log-y: expected on or off, found '" + log_y + "'");
  const double minus = cl.real("minus", 0);
  std::vector<FileArgument> inputs;
  for (const std::string& argument : cl.positional())
    inputs.push_back({"the trace", argument.substr(0, argument.find('='))});
  check_file_arguments(inputs, {{"--out", out_path}});

  std::vector<PlotSeries> series;
  for (const std::string& argument : cl.positional()) {
    const std::size_t equals = argument.find('=');
    const std::string path = argument.substr(0, equals);
    const TraceTable table = read_trace_csv(path);
    PlotSeries line;
    line.label = equals == std::string::npos ? path.substr(path.find_last_of('/') + 1) : argument.substr(equals + 1);
    // The rows of a warm start (marked in the status column) belong to
    // another energy: the line shows the run itself.
    const std::vector<double>& x = table.column(x_name, path);
    const std::vector<double>& y = table.column(y_name, path);
    for (std::size_t i = 0; i < x.size(); ++i) {
      if (i < table.status.size() && table.status[i] == "warm-start") continue;
      line.x.push_back(x[i]);
      line.y.push_back(y[i] - minus);
    }
    series.push_back(std::move(line));
  }
  PlotSpec spec;
  spec.title = cl.text("title", "");
  spec.x_label = x_name == "iter" ? "iteration" : x_name;
  spec.y_label = minus != 0 ? y_name + " - " + cl.text("minus", "") : y_name;
  spec.log_y = log_y == "on";
  const std::string svg = line_plot_svg(spec, series);
  write_file_atomically(out_path, [&](std::ostream& file) { file << svg; });
  return kExitOk;
}

}  // namespace akvf
