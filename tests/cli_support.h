#pragma once
// Helpers of the tests that drive the akvf command line in-process and
// work with files: one scratch folder per test, text in and out, the
// program's exit code and its two streams.
#include <filesystem>
#include <string>
#include <vector>

#include "akvf/mesh.h"

namespace akvf::test {

struct CliOutcome {
  int code;
  std::string out, err;
};

// akvf::run_akvf(args) with its output and error streams captured.
CliOutcome run_cli(const std::vector<std::string>& args);

// An empty folder <temp>/akvf_<name>, made anew.
std::filesystem::path scratch_dir(const std::string& name);

void write_text(const std::filesystem::path& path, const std::string& text);
std::string read_text(const std::filesystem::path& path);
// The mesh as OBJ with 17 digits (1-based faces).
void write_obj(const std::filesystem::path& path, const TriMesh& mesh);

}  // namespace akvf::test
