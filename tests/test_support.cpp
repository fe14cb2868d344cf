#include "tests/test_support.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "framework/error.h"
#include "framework/mesh_io.h"

namespace akvf::test {

TriMesh grid_disk(int nx, int ny, double jitter, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  TriMesh mesh;
  mesh.V.resize(nx * ny, 3);
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const bool interior = i > 0 && j > 0 && i + 1 < nx && j + 1 < ny;
      const double dx = interior ? u(rng) / (nx - 1) : 0, dy = interior ? u(rng) / (ny - 1) : 0;
      mesh.V.row(j * nx + i) << double(i) / (nx - 1) + dx, double(j) / (ny - 1) + dy, 0;
    }
  mesh.F.resize(2 * (nx - 1) * (ny - 1), 3);
  int f = 0;
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const int a = j * nx + i, b = a + 1, c = a + nx, d = c + 1;
      mesh.F.row(f++) << a, b, d;
      mesh.F.row(f++) << a, d, c;
    }
  return mesh;
}

TriMesh bumpy_disk(int nx, int ny) {
  TriMesh mesh = grid_disk(nx, ny);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    mesh.V(v, 2) = 0.3 * std::sin(5 * mesh.V(v, 0)) * std::cos(4 * mesh.V(v, 1));
  return mesh;
}

Eigen::MatrixXd jittered_uv(const TriMesh& mesh, double jitter, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-jitter, jitter);
  Eigen::MatrixXd UV = mesh.V.leftCols(2);
  const double spacing = std::sqrt(2.0 / mesh.num_faces());
  for (int v = 0; v < UV.rows(); ++v) UV.row(v) += spacing * Eigen::RowVector2d(u(rng), u(rng));
  return UV;
}

TriMesh parse_mesh(const std::string& text, const std::string& name) {
  std::istringstream in(text);
  return name.size() >= 4 && name.substr(name.size() - 4) == ".off" ? read_off(in, name) : read_obj(in, name);
}

std::string data_dir() {
  if (const char* dir = std::getenv("AKVF_DATA_DIR")) return std::filesystem::is_directory(dir) ? dir : "";
  const std::string beside = AKVF_SOURCE_DIR "/../shared/meshes";
  return std::filesystem::is_directory(beside) ? beside : "";
}

std::string error_message(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

void skip(const std::string& reason) { std::cout << "SKIPPED: " << reason << std::endl; }

}  // namespace akvf::test
