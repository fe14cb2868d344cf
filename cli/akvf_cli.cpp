#include "cli/akvf_cli.h"

#include <iostream>
#include <string>
#include <vector>

#include "akvf/catalog.h"
#include "akvf/error.h"
#include "akvf/internal/option_schema.h"
#include "akvf/version.h"
#include "cli/command_line.h"
#include "cli/deform_command.h"
#include "cli/exit_codes.h"
#include "cli/experiment_command.h"
#include "cli/param_command.h"
#include "cli/plot_command.h"
#include "cli/view_command.h"

namespace {

const char* kUsage =
    "usage: akvf COMMAND [options]\n"
    "\n"
    "commands:\n"
    "  param MESH   parameterize a triangle mesh (.obj, .off, .ply, .stl): a disk, or any with --cut auto\n"
    "  demo         parameterize a built-in mesh and write its outputs (no input files)\n"
    "  deform TETS  deform a tet mesh with positional constraints (.mesh, .obj or .tet)\n"
    "  plot TRACES  SVG line plot of trace CSV files (energy against iterations or seconds)\n"
    "  view UV.obj  one self-contained HTML page: the checkerboard on the surface, the layout\n"
    "  experiment MANIFEST  run a manifest of cases (shard, resume, merge); tables and plots\n"
    "  list         list energies, preconditioners and line searches\n"
    "  help         show this help (also -h, --help)\n"
    "  --version    print the version\n"
    "\n"
    "`akvf COMMAND --help` describes each command's options.\n";

void print_entries(std::ostream& out, const char* title,
                   const std::vector<std::pair<std::string, std::string>>& entries) {
  out << title << ":\n";
  for (const auto& [name, description] : entries) {
    std::string left = "  " + name;
    left.resize(std::max<std::size_t>(left.size() + 2, 24), ' ');
    out << left << description << '\n';
  }
}

int list_command(const std::vector<std::string>& args, std::ostream& out) {
  akvf::CommandLine cl(
      "akvf list [--options]\n\nLists the energies, preconditioners, solvers and line searches by name.",
      {{"options", "", "print the options reference instead (Markdown, docs/options.md)"},
       {"help", "", "show this help"}});
  cl.parse(args);
  if (cl.has("help")) {
    out << cl.help();
    return akvf::kExitOk;
  }
  if (cl.has("options")) {
    out << akvf::options_reference_markdown();
    return akvf::kExitOk;
  }
  if (!cl.positional().empty()) throw akvf::OptionsError("list takes no arguments (see --help)");
  print_entries(out, "energies (--energy)", akvf::energies_2d().entries());
  print_entries(out, "preconditioners (--precond)", akvf::preconditioners_2d().entries());
  print_entries(out, "solvers (--solver)", akvf::solvers());
  print_entries(out, "line searches (--line-search)", akvf::line_searches().entries());
  print_entries(out, "3D energies (akvf deform --energy)", akvf::energies_3d().entries());
  print_entries(out, "3D preconditioners (akvf deform --precond)", akvf::preconditioners_3d().entries());
  return akvf::kExitOk;
}

}  // namespace

namespace akvf {

int run_akvf(std::vector<std::string> args, std::ostream& out, std::ostream& err) {
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    out << kUsage;
    return args.empty() ? kExitUsageError : kExitOk;
  }
  if (args[0] == "--version" || args[0] == "version") {
    out << "akvf " << kVersion << '\n';
    return kExitOk;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  try {
    if (command == "param") return param_command(args, out, err);
    if (command == "demo") return demo_command(args, out, err);
    if (command == "deform") return deform_command(args, out, err);
    if (command == "plot") return plot_command(args, out, err);
    if (command == "view") return view_command(args, out, err);
    if (command == "experiment") return experiment_command(args, out, err);
    if (command == "list") return list_command(args, out);
    err << "akvf: unknown command '" << command << "'\n\n" << kUsage;
    return kExitUsageError;
  } catch (const InputError& e) {
    err << "error: " << e.what() << '\n';
    return kExitInputError;
  } catch (const ValidationError& e) {
    err << "error: " << e.what() << '\n';
    return kExitInputError;
  } catch (const OptionsError& e) {
    err << "error: " << e.what() << '\n';
    return kExitUsageError;
  } catch (const OutputError& e) {
    err << "error: " << e.what() << '\n';
    return kExitOutputError;
  } catch (const std::exception& e) {
    err << "error: " << e.what() << '\n';
    return kExitOptimizerFailure;
  }
}

}  // namespace akvf
