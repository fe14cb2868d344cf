#include "cli/view_command.h"

#include <filesystem>

#include "akvf/error.h"
#include "akvf/mesh_io.h"
#include "cli/command_line.h"
#include "cli/exit_codes.h"
#include "cli/file_arguments.h"
#include "io/json_text.h"
#include "io/text_utilities.h"
#include "akvf/pictures.h"

namespace akvf {

int view_command(const std::vector<std::string>& args, std::ostream& out, std::ostream& err) {
  CommandLine cl(
      "akvf view UV.{obj,ply} [--summary RUN.json] [--out VIEW.html]\n\n"
      "Writes one self-contained HTML page (nothing is fetched when it is opened): the surface\n"
      "under a checkerboard (drag to orbit, wheel to zoom), the UV layout beside it, a switch to\n"
      "colour both by distortion, and the run's summary. UV.obj is what `akvf param --out` writes.",
      {
          {"summary", "RUN.json", "a run's summary (akvf param --summary) shown beside the view"},
          {"out", "VIEW.html", "the page to write (default: the mesh's name with .html)"},
          {"title", "TEXT", "the page's title (default: the mesh's file name)"},
          {"help", "", "show this help (also -h)"},
      });
  cl.parse(args);
  if (cl.has("help")) {
    out << cl.help();
    return kExitOk;
  }
  if (cl.positional().size() != 1) throw OptionsError("expected exactly one textured mesh file (see --help)");
  const std::string path = cl.positional()[0];
  const std::string out_path = cl.text("out", std::filesystem::path(path).replace_extension(".html").string());
  const std::string summary_path = cl.text("summary", "");
  require_extension("--out", out_path, {".html", ".htm"});
  require_view();
  std::vector<FileArgument> inputs = {{"the mesh", path}};
  if (!summary_path.empty()) inputs.push_back({"--summary", summary_path});
  check_file_arguments(inputs, {{"--out", out_path}});

  Warnings warnings;
  MeshTexture texture;
  const TriMesh mesh = read_triangle_mesh(path, &warnings, &texture);
  for (const auto& warning : warnings) err << "warning: " << warning << '\n';
  require_corner_texture(mesh, texture, path, "the view (write them with akvf param --out)");
  std::string summary_text;
  if (!summary_path.empty()) {
    const nlohmann::ordered_json summary = read_json_file(summary_path);
    if (!summary.is_object())
      throw InputError(summary_path + ": not a run summary: a JSON object was expected, found " +
                       (summary.is_array() ? std::string("an array") : "a " + std::string(summary.type_name())));
    summary_text = summary.dump();
  }
  const int shown = write_view(out_path, mesh, texture.uv, texture.corner,
                               cl.text("title", std::filesystem::path(path).filename().string()), summary_text);
  out << "wrote " << out_path << " (" << count_of(mesh.num_faces(), "face");
  if (shown < mesh.num_faces()) out << ", " << shown << " shown: decimated for display";
  out << ")\n";
  return kExitOk;
}

}  // namespace akvf
