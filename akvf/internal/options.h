#pragma once
// The one conversion from the public options (parameterize.h, deform.h) to
// the pipelines' configurations; the checks are the options schema's
// (option_schema.h). The API, the command line and the experiment runner
// all go through them.
#include "akvf/deform.h"
#include "akvf/error.h"
#include "akvf/internal/deformation.h"
#include "akvf/internal/option_schema.h"
#include "akvf/internal/parameterization.h"
#include "akvf/parameterize.h"

namespace akvf {

ParamConfig param_config(const ParameterizeOptions& options);
DeformConfig deform_config(const DeformOptions& options);

// Every option's check, naming a field by its key ("exponent must be > 0,
// found -1"): what is_valid() reports.
void check_options(const ParameterizeOptions& options);
void check_options(const DeformOptions& options);

// check_options as a yes or no with the message: what is_valid() returns.
template <class Options>
bool passes_checks(const Options& options, std::string* error) {
  try {
    check_options(options);
    return true;
  } catch (const OptionsError& e) {
    if (error) *error = e.what();
    return false;
  }
}

// InputError unless `array` has `columns` columns: "V must have 3 columns
// (x, y, z), found 2".
template <class Matrix>
void require_columns(const Matrix& array, int columns, const std::string& what) {
  if (array.cols() != columns)
    throw InputError(what + " must have " + std::to_string(columns) + " columns, found " +
                     std::to_string(array.cols()));
}

// RunStatistics of a finished run.
RunStatistics run_statistics(const OptimizerResult& result, const PreconditionerStatistics& preconditioner);

// The fields ParameterizeResult and DeformResult share, from a finished run
// (the map itself, uv or x, is the caller's).
template <class Result>
void fill_run_fields(const OptimizerResult& run, const PreconditionerStatistics& preconditioner,
                     const std::string& report, const Warnings& warnings, Result* result) {
  result->status = run.status;
  result->message = run.message;
  result->trace = run.trace;
  result->statistics = run_statistics(run, preconditioner);
  result->preconditioner_report = report;
  result->warnings = warnings;
}

}  // namespace akvf
