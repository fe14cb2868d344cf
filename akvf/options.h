#pragma once
// The one conversion from the public options (parameterize.h, deform.h) to
// the pipelines' configurations; the checks are the options schema's
// (option_schema.h). The API, the command line and the experiment runner
// all go through them.
#include "akvf/deform.h"
#include "akvf/deformation.h"
#include "akvf/option_schema.h"
#include "akvf/parameterization.h"
#include "akvf/parameterize.h"

namespace akvf {

ParamConfig param_config(const ParameterizeOptions& options);
DeformConfig deform_config(const DeformOptions& options);

// Every option's check, naming a field by its key ("exponent must be > 0,
// found -1"): what is_valid() reports.
void check_options(const ParameterizeOptions& options);
void check_options(const DeformOptions& options);

// RunStatistics of a finished run.
RunStatistics run_statistics(const OptimizerResult& result, const PreconditionerStatistics& preconditioner);

}  // namespace akvf
