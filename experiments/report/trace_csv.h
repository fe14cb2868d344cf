#pragma once
// The per-iteration trace as CSV: a header, then one row per iteration with
// row 0 for the initial map. Columns:
//   iter,seconds,energy,grad_norm,step,ls_evals,flips,max_step,
//   precond_seconds,line_search_seconds[,constraint_distance],status
// (constraint_distance only for runs with positional constraints:
// framework/optimization/trace_columns.h).
// `seconds` is cumulative optimizer time; `status` is empty except on the
// last row, which says why the run stopped.
#include <fstream>
#include <map>
#include <memory>
#include <ostream>
#include <string>
#include <vector>

#include "akvf/optimizer.h"
#include "framework/optimization/trace_columns.h"

namespace akvf {

void write_trace_csv(std::ostream& out, const OptimizerResult& result);
void write_trace_csv(const std::string& path, const OptimizerResult& result);

// The trace written while the run goes, for long runs: each row the
// optimizer reports is appended (and flushed) to PATH.partial, so a run can
// be followed with `tail -f` and a killed one leaves the rows it had made
// (with an empty status). finish() writes the whole trace to PATH as
// write_trace_csv does (atomically, with the status, and with the rows of a
// warm start, which the callback does not see) and removes PATH.partial.
// A special output (/dev/stdout, a FIFO) only gets the final trace; "" is
// no trace. The partial file is created at the first row.
class GrowingTraceCsv {
 public:
  explicit GrowingTraceCsv(std::string path);
  // Appends each row to PATH.partial; always continues the run.
  IterationCallback callback();
  void finish(const OptimizerResult& result);
  // PATH.partial, or "" when this trace is not written as it grows.
  const std::string& partial_path() const { return partial_path_; }

 private:
  void append(const IterationSummary& row);
  std::string path_, partial_path_;
  std::unique_ptr<std::ofstream> partial_;
  std::vector<const TraceColumn*> partial_columns_;  // decided by the first row
};

// A trace file read back: every numeric column by its header name (the
// status column is kept as text). Throws InputError naming the file and
// line for a missing header, a short row or a non-number.
struct TraceTable {
  std::map<std::string, std::vector<double>> columns;
  std::vector<std::string> status;
  const std::vector<double>& column(const std::string& name, const std::string& file) const;
};
TraceTable read_trace_csv(const std::string& path);

}  // namespace akvf
