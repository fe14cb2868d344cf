#pragma once
// Checks on the files a command reads and writes, made before any work:
// no output may name an input or another output, and every output must be
// writable. So a typo never turns the mesh into a CSV, and a bad output path
// is found before the optimization rather than after it.
#include <string>
#include <vector>

namespace akvf {

struct FileArgument {
  std::string option;  // how the user gave it: "--trace", "the input mesh", ...
  std::string path;    // "" = not given
};

// OptionsError (a command-line error) naming both options when an output is
// the same file as an input or as another output: the same file once links
// are resolved (std::filesystem::equivalent where both exist, the normalized
// absolute path otherwise). Outputs that are character devices or FIFOs
// (/dev/null, /dev/stdout) may be named more than once. Then OutputError
// naming the path when an output cannot be written (output_file.h).
void check_file_arguments(const std::vector<FileArgument>& inputs, const std::vector<FileArgument>& outputs);

// OptionsError unless `path` ends in one of `extensions` (".obj", ...), the
// formats a writer produces. A character device or FIFO (/dev/stdout) or an
// existing folder (refused later with its own message) is not checked.
void require_extension(const std::string& option, const std::string& path, const std::vector<std::string>& extensions);

// True when `a` and `b` name the same file in the sense above.
bool same_file(const std::string& a, const std::string& b);

}  // namespace akvf
