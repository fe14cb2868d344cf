#include "tests/cli_support.h"

#include <fstream>
#include <iterator>
#include <sstream>

#include "cli/akvf_cli.h"

namespace akvf::test {

CliOutcome run_cli(const std::vector<std::string>& args) {
  std::ostringstream out, err;
  const int code = run_akvf(args, out, err);
  return {code, out.str(), err.str()};
}

std::filesystem::path scratch_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::temp_directory_path() / ("akvf_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

void write_text(const std::filesystem::path& path, const std::string& text) { std::ofstream(path) << text; }

std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

void write_obj(const std::filesystem::path& path, const TriMesh& mesh) {
  std::ofstream out(path);
  out.precision(17);
  for (int v = 0; v < mesh.V.rows(); ++v)
    out << "v " << mesh.V(v, 0) << ' ' << mesh.V(v, 1) << ' ' << mesh.V(v, 2) << '\n';
  for (int f = 0; f < mesh.F.rows(); ++f)
    out << "f " << mesh.F(f, 0) + 1 << ' ' << mesh.F(f, 1) + 1 << ' ' << mesh.F(f, 2) + 1 << '\n';
}

}  // namespace akvf::test
