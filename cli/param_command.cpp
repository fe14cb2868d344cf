#include "cli/param_command.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>

#include "akvf/catalog.h"
#include "akvf/error.h"
#include "akvf/internal/demo_mesh.h"
#include "akvf/internal/options.h"
#include "akvf/internal/parameterization.h"
#include "akvf/internal/seam_cutting.h"
#include "akvf/mesh_io.h"
#include "akvf/pictures.h"
#include "akvf/threads.h"
#include "cli/command_line.h"
#include "cli/exit_codes.h"
#include "cli/file_arguments.h"
#include "cli/run_reporting.h"
#include "cli/schema_options.h"
#include "experiments/report/run_summary.h"
#include "experiments/report/trace_csv.h"
#include "framework/mesh/chart_layout.h"
#include "framework/process/output_file.h"
#include "io/checker_texture.h"
#include "io/gltf_writer.h"
#include "io/mesh_text.h"
#include "io/ply_reader.h"
#include "io/text_reader.h"
#include "io/text_utilities.h"

namespace akvf {

namespace {

struct Outputs {
  std::string obj, trace, svg, summary, png, view;
  bool texture = false;  // --texture checker: UV.mtl and the checkerboard beside the OBJ
  int png_size = 1024;
};

std::vector<OptionSpec> optimization_options() {
  std::vector<OptionSpec> specs = schema_option_specs(parameterize_option_fields());
  specs.push_back({"quiet", "", "no per-iteration progress on stderr (also -q)"});
  specs.push_back({"help", "", "show this help (also -h)"});
  return specs;
}

// The command line's values into the API's options, checked by the schema
// (and converted as for library users, akvf/internal/options.h, when run).
ParameterizeOptions options_from(const CommandLine& cl) {
  return schema_options_from(cl, parameterize_option_fields());
}

// The --summary record: the run's options, then its outcome and the machine.
//   texture_uv_scale  the factor of the unit-square vt written (textured OBJ,
//                     GLB), or 0 when none were
//   coverage          the fraction of the UV square the map covers
Json param_summary(const std::string& mesh_file, const ParameterizeOptions& options, const ParamSetup& setup,
                   const ParamRun& run, double texture_uv_scale, double coverage) {
  Json settings;
  record_options(parameterize_option_fields(), options, &settings);
  Json record = run_record(run.result, setup.objective->lower_bound(), setup.disk.mesh.num_vertices(),
                           setup.disk.mesh.num_faces());
  record["linear_algebra"] = linear_algebra_record(run.preconditioner_statistics, run.preconditioner_report);
  record["overlap"] = Json{{"boundary_crossings", run.boundary_crossings}, {"area_fraction", run.overlap.fraction()}};
  record["distortion_energy"] = run.distortion_energy;
  record["initial_map"] = choice_name(setup.initial_map);
  if (setup.disk.cut) record["cut"] = cut_record(setup.disk, run.packing_splits);
  if (options.cut == Cut::kSeams) record["seams"] = seam_record(run.seams, options.max_distortion);
  if (setup.disk.repair.any() || setup.disk.welding.welded > 0 || !setup.disk.removed_faces.empty() ||
      !setup.disk.reoriented_faces.empty())
    record["repair"] = repair_record(setup.disk);
  if (texture_uv_scale > 0) record["texture_uv_scale"] = texture_uv_scale;
  record["uv_coverage"] = coverage;
  return single_run_summary("param", mesh_file, settings, record);
}

//   start_uv    the file's texture coordinates per vertex for --init file, or empty
//   obj_source  what the input OBJ carries besides (kept in an OBJ output), or null
int run_and_write(const TriMesh& input, const std::string& name, const ParameterizeOptions& options,
                  const Eigen::MatrixXd& start_uv, const ObjPassthrough* obj_source, const Outputs& outputs, bool quiet,
                  std::ostream& out, std::ostream& err) {
  ParamConfig config = param_config(options);
  config.start_uv = start_uv;
  const ParamSetup setup = prepare_parameterization(input, name, config);
  for (const auto& warning : setup.warnings) err << "warning: " << warning << '\n';
  const TriMesh& mesh = setup.disk.mesh;
  if (setup.disk.cut) out << name << ": " << cut_description(setup.disk) << '\n';
  out << name << ": " << count_of(mesh.num_vertices(), "vertex", "vertices") << ", "
      << count_of(mesh.num_faces(), "face") << "; energy " << config.energy << ", preconditioner "
      << config.preconditioner << ", start: ";
  if (setup.initial_map == akvf::InitialMap::kConformal || setup.initial_map == akvf::InitialMap::kBoundaryFirst)
    out << (setup.initial_map == akvf::InitialMap::kConformal ? "the conformal map" : "the boundary-first map")
        << (setup.folds_unfolded > 0
                ? ", " + count_of(setup.folds_unfolded, "vertex", "vertices") + " moved out of folds"
                : "");
  else if (config.init_from_file)
    out << "the file's map";
  else
    out << "the Tutte map" << (config.init == akvf::TutteWeights::kCotangent ? " (cotangent)" : "") << ", "
        << setup.flaps_moved << " flap vertices moved";
  if (setup.flaps_shortened > 0) out << " (" << setup.flaps_shortened << " part of the way: the boundary would cross)";
  out << '\n';

  std::vector<IterationCallback> callbacks;
  if (!quiet) callbacks.push_back(progress_printer(err));
  GrowingTraceCsv trace(outputs.trace);
  callbacks.push_back(trace.callback());
  const ParamRun run = run_parameterization(setup, config, callbacks);
  const OptimizerResult& result = run.result;
  const ParamSetup& final = final_setup(setup, run);
  const IterationSummary& last = result.trace.back();
  out << summary_line(result);
  if (!run.preconditioner_report.empty()) out << run.preconditioner_name << ": " << run.preconditioner_report << '\n';
  if (!is_normal_termination(result.status)) err << "error: " << result.message << '\n';
  if (run.boundary_crossings > 0 || run.overlap.overlapped_samples > 0)
    err << "warning: the UV map overlaps itself: " << run.boundary_crossings << " pairs of boundary edges cross, "
        << 100 * run.overlap.fraction() << " % of its area lies over another part"
        << (config.global_injectivity ? " (global injectivity keeps only a start without overlap so)\n"
                                      : " (--injectivity global prevents it)\n");

  if (config.seams) {
    out << name << ": " << seam_description(run.seams, config.max_distortion) << '\n';
    if (!run.seams.bound_met && is_normal_termination(result.status))
      err << "warning: the distortion bound " << config.max_distortion
          << " does not hold in every chart; a larger --max-distortion ends sooner\n";
  }
  const Eigen::MatrixXd UV = output_uv(final, result.x);
  const Eigen::MatrixXi UV_faces = output_uv_faces(final);
  const double coverage = square_coverage(UV_faces, UV);
  if (final.disk.num_charts() > 1)
    out << count_of(final.disk.num_charts(), "chart") << " packed"
        << (run.packing_splits > 0 ? " (" + count_of(run.packing_splits, "straight cut") + " for the packing)" : "")
        << ", covering " << 100 * coverage << " % of the UV square\n";
  double texture_uv_scale = 0;
  if (!outputs.obj.empty()) {
    MeshWriteOptions write_options;
    write_options.texture = outputs.texture ? "checker" : "none";
    write_options.obj_source = obj_source;
    texture_uv_scale = write_mesh(outputs.obj, input, UV, UV_faces, write_options);
  }
  trace.finish(result);
  if (!outputs.svg.empty())
    write_layout_svg(outputs.svg, input, UV, UV_faces,
                     name + " - " + run.preconditioner_name + ", " + std::to_string(last.iteration) +
                         " iterations, E = " + std::to_string(last.energy));
  if (!outputs.png.empty()) write_layout_png(outputs.png, input, UV, UV_faces, outputs.png_size);
  if (!outputs.summary.empty() || !outputs.view.empty()) {
    const Json summary = param_summary(name, options, final, run, texture_uv_scale, coverage);
    if (!outputs.summary.empty()) write_summary(outputs.summary, summary);
    if (!outputs.view.empty())
      write_view(outputs.view, input, UV, UV_faces, std::filesystem::path(name).filename().string(), summary.dump());
  }
  return exit_code_of(result);
}

}  // namespace

int param_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::vector<OptionSpec> specs = {
      {"out", "UV.{obj,ply,glb}",
       "write the input mesh with its `vt` (an OBJ input's normals, groups, materials and colours kept; UV.mtl, "
       "UV_checker.png: --texture); a binary PLY with per-vertex s, t "
       "(per-corner texcoord with --cut auto); or a binary glTF with the checkerboard embedded"},
      {"texture", "checker|none",
       "with --out: checker writes UV.mtl and a checkerboard UV_checker.png beside it, vt scaled into the unit "
       "square; none writes vt at the input's scale (default checker)"},
      {"trace", "TRACE.csv",
       "write one CSV row per iteration (row 0 = initial map; TRACE.csv.partial grows during the run)"},
      {"svg", "LAYOUT.svg", "write the UV layout shaded by distortion"},
      {"png", "LAYOUT.png", "write the UV layout shaded by distortion as a PNG image (any mesh size)"},
      {"png-size", "N", "the PNG's longer side in pixels, 16 to 16384 (default 1024)"},
      {"summary", "RUN.json",
       "write the run's summary: options, status, iterations, energy, memory (docs/experiments.md)"},
      {"view", "VIEW.html",
       "write one self-contained HTML page: the checkerboard on the surface (seams in red), the layout, the summary "
       "(akvf view)"},
  };
  for (auto& spec : optimization_options()) specs.push_back(spec);
  CommandLine cl(
      "akvf param MESH.{obj,off,ply,stl} [options]\n\n"
      "Parameterizes a disk-topology triangle mesh by minimizing a distortion energy\n"
      "with a preconditioned, flip-free descent (Claici et al. 2017, Algorithm 1).\n"
      "--cut auto first cuts a closed, multi-boundary, higher-genus or multi-component\n"
      "mesh into disk charts; --cut seams then adds seams until every chart's\n"
      "symmetric Dirichlet energy is at most --max-distortion (default 4.2).",
      specs);
  cl.parse(args);
  if (cl.has("help")) {
    out << cl.help();
    return kExitOk;
  }
  if (cl.positional().size() != 1) throw OptionsError("expected exactly one mesh file (see --help)");
  const ParameterizeOptions options = options_from(cl);
  const std::string& path = cl.positional()[0];
  Outputs outputs{cl.text("out", ""),     cl.text("trace", ""), cl.text("svg", ""),
                  cl.text("summary", ""), cl.text("png", ""),   cl.text("view", "")};
  if (cl.has("png-size")) {
    long long size = 0;
    if (!parse_integer(cl.text("png-size", ""), &size) || size < 16 || size > 16384)
      throw OptionsError("option --png-size must be an integer from 16 to 16384, found '" + cl.text("png-size", "") +
                         "'");
    outputs.png_size = static_cast<int>(size);
  }
  require_extension("--png", outputs.png, {".png"});
  require_extension("--view", outputs.view, {".html", ".htm"});
  if (!outputs.view.empty()) require_view();
  const std::string texture_mode = cl.text("texture", "checker");
  if (texture_mode != "checker" && texture_mode != "none")
    throw OptionsError("option --texture must be checker or none, found '" + texture_mode + "'");
  // Not beside a device or FIFO (--out /dev/null writes no /dev/null.mtl).
  outputs.texture =
      texture_mode == "checker" && lowercase_extension(outputs.obj) == ".obj" && !is_special_output(outputs.obj);
  require_extension("--out", outputs.obj, {".obj", ".ply", ".glb"});
  std::vector<FileArgument> written = {{"--out", outputs.obj}, {"--trace", outputs.trace},
                                       {"--svg", outputs.svg}, {"--summary", outputs.summary},
                                       {"--png", outputs.png}, {"--view", outputs.view}};
  if (outputs.texture) {  // the files written beside the OBJ are outputs too
    const TextureFiles files = texture_files_for(outputs.obj);
    written.push_back({"the MTL of --out", files.mtl});
    written.push_back({"the checkerboard of --out", files.png});
  }
  check_file_arguments({{"the input mesh", path}}, written);
  const ThreadLimit threads(options.threads);
  reset_peak_memory();
  Warnings warnings;
  MeshTexture texture;
  // An OBJ input's statements are kept for an OBJ output, and its material
  // files are checked against every output.
  ObjPassthrough obj_source;
  const bool obj_output = lowercase_extension(outputs.obj) == ".obj";
  const bool any_output =
      std::any_of(written.begin(), written.end(), [](const FileArgument& f) { return !f.path.empty(); });
  const bool keep_obj = lowercase_extension(path) == ".obj" && any_output;
  const TriMesh input = read_triangle_mesh(path, &warnings, &texture, keep_obj ? &obj_source : nullptr);
  for (const auto& warning : warnings) err << "warning: " << warning << '\n';
  // The input's material libraries and their images are inputs too.
  std::vector<FileArgument> materials;
  for (const std::string& file : material_files(path, obj_source))
    materials.push_back({"the input's material file", file});
  if (!materials.empty()) check_file_arguments(materials, written);
  const Eigen::MatrixXd start_uv =
      options.init == akvf::InitialMap::kFile ? per_vertex_uv(input, texture, path) : Eigen::MatrixXd();
  return run_and_write(input, path, options, start_uv, obj_output && !obj_source.empty() ? &obj_source : nullptr,
                       outputs, cl.has("quiet"), out, err);
}

int demo_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  std::vector<OptionSpec> specs = {{"out-dir", "DIR", "where to write the outputs (default akvf-demo)"}};
  for (auto& spec : optimization_options()) specs.push_back(spec);
  CommandLine cl(
      "akvf demo [--out-dir DIR] [options]\n\n"
      "Builds the bent bar of the paper's Figure 2 in code (a developable strip rolled\n"
      "onto a cylinder), parameterizes it, and writes demo_uv.obj (with demo_uv.mtl and the\n"
      "checkerboard demo_uv_checker.png), demo_trace.csv, demo_layout.svg, demo_summary.json\n"
      "and demo_view.html (open it in a browser). The optimum energy is exactly the lower bound 4.",
      specs);
  cl.parse(args);
  if (cl.has("help")) {
    out << cl.help();
    return kExitOk;
  }
  if (!cl.positional().empty()) throw OptionsError("demo takes no mesh file (see --help)");
  const ParameterizeOptions options = options_from(cl);
  const std::filesystem::path dir = cl.text("out-dir", "akvf-demo");
  create_output_folder(dir.string());
  Outputs outputs{(dir / "demo_uv.obj").string(),
                  (dir / "demo_trace.csv").string(),
                  (dir / "demo_layout.svg").string(),
                  (dir / "demo_summary.json").string(),
                  "",
                  view_available() ? (dir / "demo_view.html").string() : ""};
  outputs.texture = true;
  const TextureFiles texture = texture_files_for(outputs.obj);
  check_file_arguments({}, {{"the UV OBJ", outputs.obj},
                            {"its MTL", texture.mtl},
                            {"its checkerboard", texture.png},
                            {"the trace", outputs.trace},
                            {"the layout", outputs.svg},
                            {"the summary", outputs.summary},
                            {"the view", outputs.view}});
  const ThreadLimit threads(options.threads);
  const int code = run_and_write(bent_bar(), "bent-bar", options, {}, nullptr, outputs, cl.has("quiet"), out, err);
  out << "wrote " << outputs.obj << " (+ " << texture.mtl_name << ", " << texture.png_name << "), " << outputs.trace
      << ", " << outputs.svg << ", " << outputs.summary;
  if (!outputs.view.empty()) out << ", " << outputs.view;
  out << '\n';
  if (outputs.view.empty())
    err << "warning: no demo_view.html: this build has no three.js (install libjs-three: bash scripts/setup.sh)\n";
  return code;
}

}  // namespace akvf
