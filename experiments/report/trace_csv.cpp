#include "experiments/report/trace_csv.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include "akvf/error.h"
#include "framework/optimization/trace_columns.h"
#include "framework/process/output_file.h"
#include "io/text_reader.h"

namespace akvf {

namespace {

using Columns = std::vector<const TraceColumn*>;

void write_header(std::ostream& out, const Columns& columns) {
  for (const TraceColumn* column : columns) out << column->name << ',';
  out << "status\n";
  out << std::setprecision(17);
}

// A row's numeric fields, each followed by a comma (the status comes last).
void write_fields(std::ostream& out, const Columns& columns, const IterationSummary& row) {
  for (const TraceColumn* column : columns) {
    const double value = column->value(row);
    if (column->integer)
      out << static_cast<long long>(value) << ',';
    else
      out << value << ',';
  }
}

}  // namespace

void write_trace_csv(std::ostream& out, const OptimizerResult& result) {
  const Columns columns = present_trace_columns(result.trace);
  write_header(out, columns);
  std::string status_cell = status_with_reason(result);  // one CSV field: no commas
  std::replace(status_cell.begin(), status_cell.end(), ',', ';');
  for (std::size_t i = 0; i < result.trace.size(); ++i) {
    write_fields(out, columns, result.trace[i]);
    out << trace_status_cell(result.trace, i, status_cell) << '\n';
  }
}

void write_trace_csv(const std::string& path, const OptimizerResult& result) {
  write_file_atomically(path, [&](std::ostream& out) { write_trace_csv(out, result); });
}

GrowingTraceCsv::GrowingTraceCsv(std::string path) : path_(std::move(path)) {
  if (!path_.empty() && !is_special_output(path_)) partial_path_ = sibling_path(resolve_output_path(path_), ".partial");
}

IterationCallback GrowingTraceCsv::callback() {
  return [this](const IterationSummary& row, const Eigen::VectorXd&) {
    append(row);
    return CallbackAction::kContinue;
  };
}

void GrowingTraceCsv::append(const IterationSummary& row) {
  if (partial_path_.empty()) return;
  if (!partial_) {
    // A regular file or nothing at PATH.partial: anything else (a link, a
    // folder, a device) is left alone and the trace only written at the end.
    std::error_code error;
    const auto status = std::filesystem::symlink_status(partial_path_, error);
    if (std::filesystem::exists(status) && !std::filesystem::is_regular_file(status)) {
      partial_path_.clear();
      return;
    }
    partial_ = std::make_unique<std::ofstream>(partial_path_, std::ios::trunc);
    if (!*partial_) throw OutputError(partial_path_ + ": cannot write the growing trace");
    partial_columns_ = present_trace_columns(row);
    write_header(*partial_, partial_columns_);
  }
  write_fields(*partial_, partial_columns_, row);
  *partial_ << '\n' << std::flush;
}

void GrowingTraceCsv::finish(const OptimizerResult& result) {
  if (path_.empty()) return;
  write_trace_csv(path_, result);
  if (partial_) {
    partial_.reset();
    std::error_code ignored;
    std::filesystem::remove(partial_path_, ignored);
  }
}

namespace {

std::vector<std::string> split_commas(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) fields.push_back(field);
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

}  // namespace

const std::vector<double>& TraceTable::column(const std::string& name, const std::string& file) const {
  const auto found = columns.find(name);
  if (found == columns.end()) throw InputError(file + ": no column '" + name + "' in the trace");
  return found->second;
}

TraceTable read_trace_csv(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": cannot open the trace file");
  skip_utf8_bom(in);
  std::string line;
  if (!std::getline(in, line)) throw InputError(path, 1, "empty file, expected a CSV header");
  const std::vector<std::string> header = split_commas(line);
  TraceTable table;
  for (long number = 2; std::getline(in, line); ++number) {
    if (line.empty()) continue;
    const std::vector<std::string> fields = split_commas(line);
    if (fields.size() != header.size())
      throw InputError(path, number,
                       "expected " + std::to_string(header.size()) + " fields, found " + std::to_string(fields.size()));
    for (std::size_t c = 0; c < header.size(); ++c) {
      if (header[c] == "status") {
        table.status.push_back(fields[c]);
        continue;
      }
      double value = 0;
      if (!parse_real(fields[c], &value) && fields[c] != "inf" && fields[c] != "nan")
        throw InputError(path, number, "column " + header[c] + ": '" + fields[c] + "' is not a number");
      if (fields[c] == "inf") value = std::numeric_limits<double>::infinity();
      if (fields[c] == "nan") value = std::numeric_limits<double>::quiet_NaN();
      table.columns[header[c]].push_back(value);
    }
  }
  if (table.status.empty() && table.columns.empty())
    throw InputError(path, 1, "the trace has a header but no rows (a run that wrote none, or a file cut short)");
  return table;
}

}  // namespace akvf
