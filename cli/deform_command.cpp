#include "cli/deform_command.h"

#include "akvf/catalog.h"
#include "akvf/error.h"
#include "akvf/internal/deformation.h"
#include "akvf/internal/options.h"
#include "akvf/internal/slim_cube.h"
#include "akvf/tet_mesh_io.h"
#include "akvf/threads.h"
#include "cli/command_line.h"
#include "cli/exit_codes.h"
#include "cli/file_arguments.h"
#include "cli/run_reporting.h"
#include "cli/schema_options.h"
#include "experiments/report/run_summary.h"
#include "experiments/report/trace_csv.h"
#include "io/constraints_io.h"
#include "io/mesh_text.h"
#include "io/text_utilities.h"

namespace akvf {

int deform_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::vector<OptionSpec> specs = {
      {"constraints", "FILE", "one `vertex_index x y z` per line (0-based), # comments"},
      {"preset", "NAME", "slim-cube: the SLIM paper's twisted cube (Figure 8)"},
      {"out", "OUT.mesh", "write the deformed mesh (.mesh MEDIT or .vtk VTK legacy)"},
      {"trace", "TRACE.csv",
       "one CSV row per iteration; flips counts inverted tets (TRACE.csv.partial grows during the run)"},
      {"summary", "RUN.json",
       "write the run's summary: options, status, iterations, energy, memory (docs/experiments.md)"},
  };
  for (const OptionSpec& spec : schema_option_specs(deform_option_fields())) specs.push_back(spec);
  specs.push_back({"quiet", "", "no per-iteration progress on stderr (also -q)"});
  specs.push_back({"help", "", "show this help (also -h)"});
  CommandLine cl(
      "akvf deform TETMESH.{mesh,msh,obj,tet} (--constraints FILE | --preset slim-cube) [options]\n\n"
      "Deforms a tet mesh by minimizing a distortion energy plus soft positional constraints\n"
      "w sum |x_i - p_i|^2 from the rest shape, with a flip-free preconditioned descent (Sec. 6.2).",
      specs);
  cl.parse(args);
  if (cl.has("help")) {
    out << cl.help();
    return kExitOk;
  }
  if (cl.positional().size() != 1) throw OptionsError("expected exactly one tet mesh file (see --help)");
  if (cl.has("constraints") == cl.has("preset")) throw OptionsError("give exactly one of --constraints and --preset");
  const std::string preset = cl.text("preset", "");
  if (cl.has("preset") && preset != "slim-cube")
    throw OptionsError("unknown preset '" + preset + "' (valid: slim-cube)");
  if (cl.has("hard") && cl.has("weight")) throw OptionsError("option --weight has no effect with --hard");
  // Checked by the schema, converted as for library users (akvf/internal/options.h).
  const DeformOptions options = schema_options_from(cl, deform_option_fields());
  const DeformConfig config = deform_config(options);
  const std::string out_path = cl.text("out", ""), trace_path = cl.text("trace", ""),
                    summary_path = cl.text("summary", "");
  require_extension("--out", out_path, {".mesh", ".vtk"});
  const std::string& path = cl.positional()[0];
  check_file_arguments({{"the input mesh", path}, {"--constraints", cl.text("constraints", "")}},
                       {{"--out", out_path}, {"--trace", trace_path}, {"--summary", summary_path}});
  const ThreadLimit threads(config.threads);
  reset_peak_memory();

  Warnings read_warnings;
  const TetMesh input = read_tet_mesh(path, &read_warnings);
  for (const auto& warning : read_warnings) err << "warning: " << warning << '\n';
  const PositionConstraints constraints = cl.has("preset")
                                              ? slim_cube_constraints(input)
                                              : read_constraints_file(cl.text("constraints", ""), input.num_vertices());
  std::vector<IterationCallback> callbacks;
  if (!cl.has("quiet")) callbacks.push_back(progress_printer(err));
  GrowingTraceCsv trace(trace_path);
  callbacks.push_back(trace.callback());
  const DeformRun run = run_deformation(input, path, constraints, config, callbacks);
  for (const auto& warning : run.warnings) err << "warning: " << warning << '\n';
  const TetMesh& mesh = run.prepared.mesh;
  out << path << ": " << count_of(mesh.num_vertices(), "vertex", "vertices") << ", " << count_of(mesh.num_tets(), "tet")
      << ", " << constraints.vertices.size() << " constrained vertices; energy " << config.energy << ", preconditioner "
      << config.preconditioner << '\n'
      << summary_line(run.result);
  if (!run.preconditioner_report.empty()) out << config.preconditioner << ": " << run.preconditioner_report << '\n';
  if (!is_normal_termination(run.result.status)) err << "error: " << run.result.message << '\n';

  if (!out_path.empty()) {
    const TetMesh deformed = run.prepared.in_input_numbering(unstack_rows(run.result.x, 3), input);
    if (lowercase_extension(out_path) == ".vtk")
      write_vtk(out_path, deformed);
    else
      write_medit(out_path, deformed);
  }
  trace.finish(run.result);
  if (!summary_path.empty()) {
    Json settings;
    record_options(deform_option_fields(), options, &settings);
    settings["preset"] = preset;
    settings["constraints"] = cl.text("constraints", "");
    Json record = run_record(run.result, energies_3d().create(options.energy, {options.exponent})->lower_bound(),
                             mesh.num_vertices(), mesh.num_tets());
    record["linear_algebra"] = linear_algebra_record(run.preconditioner_statistics, run.preconditioner_report);
    write_summary(summary_path, single_run_summary("deform", path, settings, record));
  }
  return exit_code_of(run.result);
}

}  // namespace akvf
