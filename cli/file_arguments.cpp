#include "cli/file_arguments.h"

#include <filesystem>

#include "akvf/error.h"
#include "framework/process/output_file.h"
#include "io/mesh_text.h"

namespace akvf {

namespace fs = std::filesystem;

namespace {

// The absolute path with "." and ".." removed and every link of an existing
// prefix resolved, then the output's own last link followed.
fs::path normalized(const std::string& path) {
  std::error_code error;
  const fs::path resolved = fs::weakly_canonical(fs::absolute(resolve_output_path(path)), error);
  return error ? fs::absolute(path).lexically_normal() : resolved;
}

}  // namespace

bool same_file(const std::string& a, const std::string& b) {
  std::error_code error;
  if (fs::exists(a, error) && fs::exists(b, error)) return fs::equivalent(a, b, error) && !error;
  return normalized(a) == normalized(b);
}

void require_extension(const std::string& option, const std::string& path, const std::vector<std::string>& extensions) {
  std::error_code error;
  if (path.empty() || is_special_output(path) || fs::is_directory(resolve_output_path(path), error)) return;
  const std::string found = lowercase_extension(path);
  std::string list;
  for (const std::string& e : extensions) {
    if (e == found) return;
    list += (list.empty() ? "" : ", ") + e;
  }
  throw OptionsError("option " + option + ": cannot write '" + path + "': no writer produces '" +
                     (found.empty() ? "(no extension)" : found) + "' (formats: " + list + ")");
}

void check_file_arguments(const std::vector<FileArgument>& inputs, const std::vector<FileArgument>& outputs) {
  for (std::size_t o = 0; o < outputs.size(); ++o) {
    const FileArgument& output = outputs[o];
    if (output.path.empty()) continue;
    for (const FileArgument& input : inputs)
      if (!input.path.empty() && same_file(output.path, input.path))
        throw OptionsError(output.option + " " + output.path + " is the same file as " + input.option + " " +
                           input.path + "; an output never replaces an input: choose another name");
    if (is_special_output(output.path)) continue;
    for (std::size_t p = 0; p < o; ++p)
      if (!outputs[p].path.empty() && same_file(output.path, outputs[p].path))
        throw OptionsError(outputs[p].option + " and " + output.option + " both name " + output.path +
                           "; each output needs a file of its own");
  }
  for (const FileArgument& output : outputs) {
    try {
      check_output_writable(output.path);
    } catch (const OutputError& error) {
      if (output.option.rfind("--", 0) == 0) throw;
      throw OutputError(output.option + ": " + error.what());  // a side file: say whose
    }
  }
}

}  // namespace akvf
