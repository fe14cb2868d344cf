#include "experiments/report/experiment_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <sstream>

#include "experiments/report/line_plot.h"
#include "experiments/report/text_utilities.h"
#include "experiments/report/trace_csv.h"
#include "experiments/runner/experiment_runner.h"
#include "experiments/runner/manifest.h"
#include "framework/process/error.h"
#include "framework/process/output_file.h"

namespace akvf {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;

namespace {

std::string number(double v, int digits = 4) {
  std::ostringstream text;
  text << std::setprecision(digits) << v;
  return text.str();
}

// The Markdown cell of one case.
std::string cell(const Json& s, const std::string& value) {
  if (s.is_null()) return "not run";
  const std::string status = s["status"];
  if (status == "missing") return "mesh not available";
  if (status == "error") return "error: " + s["message"].get<std::string>();
  const std::string iterations = std::to_string(s["iterations"].get<int>()) + " it";
  if (value == "energy") return number(s["final_energy"].get<double>(), 8) + " (" + iterations + ")";
  if (s["reached"].get<bool>()) return number(s["seconds"].get<double>(), 3) + " s (" + iterations + ")";
  return "not reached (" + status + "): " + iterations + ", " + number(s["seconds"].get<double>(), 3) + " s, E " +
         number(s["final_energy"].get<double>(), 7) + ", gradient " + number(s["grad_norm"].get<double>(), 2);
}

std::string csv_field(const Json& s, const char* key) {
  if (!s.contains(key)) return "";
  const Json& v = s[key];
  if (v.is_string()) {
    std::string text = v.get<std::string>();
    for (char& ch : text)
      if (ch == ',' || ch == '\n') ch = ';';
    return text;
  }
  if (v.is_boolean()) return v.get<bool>() ? "1" : "0";
  std::ostringstream text;
  text << std::setprecision(17) << v.get<double>();
  return text.str();
}

}  // namespace

std::string write_experiment_report(const std::string& out_dir) {
  const std::string manifest_path = join_path(out_dir, "manifest.json");
  if (!fs::exists(manifest_path)) throw InputError(out_dir + ": not a results folder (no manifest.json)");
  const Manifest manifest = parse_manifest(read_text_file(manifest_path), manifest_path);
  std::vector<Json> summaries(manifest.cases.size());
  for (const ExperimentCase& c : manifest.cases) {
    const std::string path = join_path(join_path(join_path(out_dir, "cases"), c.id), "summary.json");
    if (fs::exists(path)) summaries[c.index] = Json::parse(read_text_file(path));
  }
  // Paper columns, in first-seen order.
  std::vector<std::string> paper_columns;
  for (const ManifestMesh& mesh : manifest.meshes)
    for (const auto& [column, value] : mesh.paper)
      if (std::find(paper_columns.begin(), paper_columns.end(), column) == paper_columns.end())
        paper_columns.push_back(column);

  std::ostringstream md;
  md << "| mesh | faces | ";
  for (const std::string& method : manifest.methods) md << method << " | ";
  for (const std::string& column : paper_columns) md << "paper " << column << " | ";
  md << "note |\n|---|---|";
  for (std::size_t i = 0; i < manifest.methods.size() + paper_columns.size(); ++i) md << "---|";
  md << "---|\n";
  const std::size_t per_mesh = manifest.methods.size();
  for (std::size_t i = 0; i < manifest.meshes.size(); ++i) {
    const ManifestMesh& mesh = manifest.meshes[i];
    std::string faces = "";
    for (std::size_t j = 0; j < per_mesh; ++j) {
      const Json& s = summaries[i * per_mesh + j];
      if (!s.is_null() && s.contains("elements")) faces = std::to_string(s["elements"].get<int>());
    }
    md << "| " << mesh.label << " | " << faces << " | ";
    for (std::size_t j = 0; j < per_mesh; ++j) md << cell(summaries[i * per_mesh + j], manifest.table_value) << " | ";
    for (const std::string& column : paper_columns) {
      const auto found =
          std::find_if(mesh.paper.begin(), mesh.paper.end(), [&](const auto& entry) { return entry.first == column; });
      md << (found != mesh.paper.end() ? number(found->second) : "") << " | ";
    }
    md << (mesh.missing.empty() ? mesh.note : "not available: " + mesh.missing) << " |\n";
  }
  const std::string table = md.str();
  write_file_atomically(join_path(out_dir, "table.md"), [&](std::ostream& out) { out << table; });

  write_file_atomically(join_path(out_dir, "table.csv"), [&](std::ostream& out) {
    const char* keys[] = {"mesh",        "method",    "status",    "reached",  "iterations", "seconds", "final_energy",
                          "lower_bound", "grad_norm", "max_flips", "vertices", "elements",   "message"};
    for (std::size_t k = 0; k < std::size(keys); ++k) out << (k ? "," : "") << keys[k];
    out << '\n';
    for (std::size_t c = 0; c < summaries.size(); ++c) {
      const Json& s = summaries[c];
      if (s.is_null()) {
        out << manifest.cases[c].mesh_label << ',' << manifest.cases[c].method_label << ",not-run\n";
        continue;
      }
      for (std::size_t k = 0; k < std::size(keys); ++k) out << (k ? "," : "") << csv_field(s, keys[k]);
      out << '\n';
    }
  });

  fs::create_directories(join_path(out_dir, "plots"));
  for (std::size_t i = 0; i < manifest.meshes.size(); ++i) {
    for (const char* axis : {"iter", "seconds"}) {
      std::vector<PlotSeries> series;
      double lower_bound = 0;
      for (std::size_t j = 0; j < per_mesh; ++j) {
        const ExperimentCase& c = manifest.cases[i * per_mesh + j];
        const Json& s = summaries[c.index];
        const std::string trace = join_path(join_path(join_path(out_dir, "cases"), c.id), "trace.csv");
        if (s.is_null() || !s.contains("lower_bound") || !fs::exists(trace)) continue;
        lower_bound = s["lower_bound"].get<double>();
        const TraceTable table_of_trace = read_trace_csv(trace);
        PlotSeries line;
        line.label = c.method_label;
        line.x = table_of_trace.column(axis, trace);
        line.y = table_of_trace.column("energy", trace);
        for (double& y : line.y) y -= lower_bound;
        series.push_back(std::move(line));
      }
      if (series.empty()) continue;
      PlotSpec spec;
      spec.title = manifest.meshes[i].label + ": energy above its lower bound";
      spec.x_label = std::string(axis) == "iter" ? "iteration" : "seconds";
      spec.y_label = "E - " + number(lower_bound);
      spec.log_y = true;
      std::string svg;
      try {
        svg = line_plot_svg(spec, series);
      } catch (const OptionsError&) {
        continue;  // nothing positive to draw (every run at the bound)
      }
      const std::string name =
          slug(manifest.meshes[i].label) + (std::string(axis) == "iter" ? "-iterations" : "-seconds");
      write_file_atomically(join_path(join_path(out_dir, "plots"), name + ".svg"),
                            [&](std::ostream& out) { out << svg; });
    }
  }
  return table;
}

}  // namespace akvf
