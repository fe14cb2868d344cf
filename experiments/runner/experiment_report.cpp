#include "experiments/runner/experiment_report.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <utility>

#include "akvf/error.h"
#include "experiments/report/trace_csv.h"
#include "experiments/runner/experiment_runner.h"
#include "experiments/runner/manifest.h"
#include "framework/process/output_file.h"
#include "io/json_text.h"
#include "io/text_utilities.h"
#include "pictures/html_view.h"
#include "pictures/line_plot.h"

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

// The case's pictures and view beside its id, as links relative to the folder.
std::string case_links(const std::string& out_dir, const ExperimentCase& c, const Json& summary) {
  const std::string folder = "cases/" + c.id + "/";
  std::string links;
  for (const char* name : {"view.html", "final.svg", "final.png", "trace.csv"})
    if (fs::exists(join_path(out_dir, folder + name)))
      links += " <a href=\"" + xml_escape(folder + name) + "\">" + name + "</a>";
  if (fs::exists(join_path(out_dir, folder + "view.html")) && summary.contains("elements") &&
      summary["elements"].get<long long>() > kViewFaceLimit)
    links += " (the view is decimated for display to at most " + std::to_string(kViewFaceLimit) + " of its " +
             std::to_string(summary["elements"].get<long long>()) + " faces)";
  return links;
}

// OUT/index.html: the table, the plots, and per case its view, final layout
// and trace (views exist where the run had --views; large ones decimated).
void write_index_html(const std::string& out_dir, const Manifest& manifest, const std::vector<Json>& summaries,
                      const std::vector<std::string>& header, const std::vector<std::vector<std::string>>& rows,
                      const std::vector<std::string>& plots) {
  const std::string title = manifest.name.empty() ? "akvf experiment" : manifest.name;
  write_file_atomically(join_path(out_dir, "index.html"), [&](std::ostream& out) {
    out << "<!doctype html>\n<html lang=\"en\">\n<head>\n<meta charset=\"utf-8\">\n<title>" << xml_escape(title)
        << "</title>\n<style>body{font:14px/1.4 system-ui,sans-serif;margin:16px}table{border-collapse:collapse}"
           "td,th{border:1px solid #ccc;padding:3px 8px;text-align:left;vertical-align:top}"
           "img{max-width:48%;margin:4px}</style>\n</head>\n<body>\n<h1>"
        << xml_escape(title) << "</h1>\n";
    if (!manifest.description.empty()) out << "<p>" << xml_escape(manifest.description) << "</p>\n";
    out << "<table>\n<tr>";
    for (const std::string& text : header) out << "<th>" << xml_escape(text) << "</th>";
    out << "</tr>\n";
    for (const auto& row : rows) {
      out << "<tr>";
      for (const std::string& text : row) out << "<td>" << xml_escape(text) << "</td>";
      out << "</tr>\n";
    }
    out << "</table>\n<h2>Plots</h2>\n";
    for (const std::string& plot : plots)
      out << "<img src=\"" << xml_escape(plot) << "\" alt=\"" << xml_escape(plot) << "\">\n";
    out << "<h2>Cases</h2>\n<ul>\n";
    for (const ExperimentCase& c : manifest.cases)
      out << "<li>" << xml_escape(c.mesh_label + " / " + c.method_label) << ":"
          << case_links(out_dir, c, summaries[c.index]) << "</li>\n";
    out << "</ul>\n</body>\n</html>\n";
  });
}

// OUT/plots/seconds-per-iteration.svg: each method's seconds per iteration
// against the mesh's element count, log-log (how the cost of an iteration
// grows with the mesh: the question of the paper's Figure 6), when the
// finished cases cover at least two sizes. A slope of 1 is linear cost.
void write_scaling_plot(const std::string& out_dir, const Manifest& manifest, const std::vector<Json>& summaries) {
  const std::size_t per_mesh = manifest.methods.size();
  std::vector<PlotSeries> series;
  std::set<long> sizes;
  for (std::size_t j = 0; j < per_mesh; ++j) {
    std::vector<std::pair<double, double>> points;  // (elements, seconds per iteration)
    for (std::size_t i = 0; i < manifest.meshes.size(); ++i) {
      const Json& s = summaries[i * per_mesh + j];
      if (s.is_null() || !s.contains("elements") || !s.contains("seconds") || !s.contains("iterations")) continue;
      const int iterations = s["iterations"].get<int>();
      if (iterations < 1) continue;
      points.emplace_back(s["elements"].get<double>(), s["seconds"].get<double>() / iterations);
      sizes.insert(s["elements"].get<long>());
    }
    if (points.empty()) continue;
    std::sort(points.begin(), points.end());
    PlotSeries line;
    line.label = manifest.methods[j];
    for (const auto& [elements, seconds] : points) {
      line.x.push_back(elements);
      line.y.push_back(seconds);
    }
    series.push_back(std::move(line));
  }
  if (sizes.size() < 2) return;
  PlotSpec spec;
  spec.title = "seconds per iteration against the mesh's size";
  spec.x_label = "elements (faces or tets)";
  spec.y_label = "seconds per iteration";
  spec.log_x = spec.log_y = true;
  const std::string svg = line_plot_svg(spec, series);
  write_file_atomically(join_path(join_path(out_dir, "plots"), "seconds-per-iteration.svg"),
                        [&](std::ostream& out) { out << svg; });
}

}  // namespace

std::string write_experiment_report(const std::string& out_dir) {
  const std::string manifest_path = join_path(out_dir, "manifest.json");
  if (!fs::exists(manifest_path)) throw InputError(out_dir + ": not a results folder (no manifest.json)");
  const Manifest manifest = parse_manifest(read_text_file(manifest_path), manifest_path);
  std::vector<Json> summaries(manifest.cases.size());
  for (const ExperimentCase& c : manifest.cases) {
    const std::string path = join_path(join_path(join_path(out_dir, "cases"), c.id), "summary.json");
    if (fs::exists(path)) summaries[c.index] = read_json_file(path);
  }
  // Paper columns, in first-seen order.
  std::vector<std::string> paper_columns;
  for (const ManifestMesh& mesh : manifest.meshes)
    for (const auto& [column, value] : mesh.paper)
      if (std::find(paper_columns.begin(), paper_columns.end(), column) == paper_columns.end())
        paper_columns.push_back(column);

  // The table as cells, written as Markdown (table.md) and HTML (index.html).
  std::vector<std::vector<std::string>> rows;
  std::vector<std::string> header = {"mesh", "faces"};
  for (const std::string& method : manifest.methods) header.push_back(method);
  for (const std::string& column : paper_columns) header.push_back("paper " + column);
  header.push_back("note");
  const std::size_t per_mesh = manifest.methods.size();
  for (std::size_t i = 0; i < manifest.meshes.size(); ++i) {
    const ManifestMesh& mesh = manifest.meshes[i];
    std::string faces = "";
    for (std::size_t j = 0; j < per_mesh; ++j) {
      const Json& s = summaries[i * per_mesh + j];
      if (!s.is_null() && s.contains("elements")) faces = std::to_string(s["elements"].get<int>());
    }
    std::vector<std::string> row = {mesh.label, faces};
    for (std::size_t j = 0; j < per_mesh; ++j) row.push_back(cell(summaries[i * per_mesh + j], manifest.table_value));
    for (const std::string& column : paper_columns) {
      const auto found =
          std::find_if(mesh.paper.begin(), mesh.paper.end(), [&](const auto& entry) { return entry.first == column; });
      row.push_back(found != mesh.paper.end() ? number(found->second) : "");
    }
    row.push_back(mesh.missing.empty() ? mesh.note : "not available: " + mesh.missing);
    rows.push_back(std::move(row));
  }
  std::ostringstream md;
  md << "|";
  for (const std::string& title : header) md << " " << title << " |";
  md << "\n|";
  for (std::size_t k = 0; k < header.size(); ++k) md << "---|";
  md << "\n";
  for (const auto& row : rows) {
    md << "|";
    for (const std::string& text : row) md << " " << text << " |";
    md << "\n";
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
  write_scaling_plot(out_dir, manifest, summaries);
  // Every plot in the folder (also those of a run whose traces are gone).
  std::vector<std::string> plots;
  for (const auto& entry : fs::directory_iterator(join_path(out_dir, "plots")))
    if (entry.path().extension() == ".svg") plots.push_back("plots/" + entry.path().filename().string());
  std::sort(plots.begin(), plots.end());
  write_index_html(out_dir, manifest, summaries, header, rows, plots);
  return table;
}

}  // namespace akvf
