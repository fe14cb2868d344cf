// akvf: isometry-aware preconditioned mesh parameterization.
#include <iostream>
#include <string>
#include <vector>

#include "experiments/catalog.h"
#include "experiments/exit_codes.h"
#include "experiments/native_runtime.h"
#include "experiments/param_command.h"
#include "framework/error.h"

namespace {

const char* kUsage =
    "usage: akvf COMMAND [options]\n"
    "\n"
    "commands:\n"
    "  param MESH   parameterize a disk-topology triangle mesh (.obj or .off)\n"
    "  demo         parameterize a built-in mesh and write its outputs (no input files)\n"
    "  list         list energies, preconditioners and line searches\n"
    "  help         show this help\n"
    "\n"
    "`akvf COMMAND --help` describes each command's options.\n";

template <class RegistryType>
void print_entries(std::ostream& out, const char* title, const RegistryType& registry) {
  out << title << ":\n";
  for (const auto& [name, description] : registry.entries()) {
    std::string left = "  " + name;
    left.resize(std::max<std::size_t>(left.size() + 2, 24), ' ');
    out << left << description << '\n';
  }
}

int list_command(std::ostream& out) {
  print_entries(out, "energies", akvf::energies_2d());
  print_entries(out, "preconditioners", akvf::preconditioners_2d());
  print_entries(out, "line searches", akvf::line_searches());
  return akvf::kExitOk;
}

}  // namespace

int main(int argc, char** argv) {
  akvf::configure_native_runtime(argv);
  std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "help" || args[0] == "--help" || args[0] == "-h") {
    std::cout << kUsage;
    return args.empty() ? akvf::kExitUsageError : akvf::kExitOk;
  }
  const std::string command = args[0];
  args.erase(args.begin());
  try {
    if (command == "param") return akvf::param_command(args, std::cout, std::cerr);
    if (command == "demo") return akvf::demo_command(args, std::cout, std::cerr);
    if (command == "list") return list_command(std::cout);
    std::cerr << "akvf: unknown command '" << command << "'\n\n" << kUsage;
    return akvf::kExitUsageError;
  } catch (const akvf::InputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return akvf::kExitInputError;
  } catch (const akvf::ValidationError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return akvf::kExitInputError;
  } catch (const akvf::OptionsError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return akvf::kExitUsageError;
  } catch (const akvf::OutputError& e) {
    std::cerr << "error: " << e.what() << '\n';
    return akvf::kExitOutputError;
  } catch (const std::exception& e) {
    std::cerr << "error: " << e.what() << '\n';
    return akvf::kExitOptimizerFailure;
  }
}
