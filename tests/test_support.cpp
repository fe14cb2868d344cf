#include "tests/test_support.h"

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>

#include "akvf/error.h"
#include "akvf/mesh_io.h"
#include "framework/mesh/mesh_subdivision.h"
#include "framework/mesh/tet_validation.h"

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

TriMesh torus(int n, int dropped_faces) {
  TriMesh m;
  m.V.resize(n * n, 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double u = 2 * M_PI * i / n, v = 2 * M_PI * j / n;
      m.V.row(j * n + i) << (2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v);
    }
  m.F.resize(2 * n * n - dropped_faces, 3);
  int f = 0;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int a = j * n + i, b = j * n + (i + 1) % n, c = ((j + 1) % n) * n + i, d = ((j + 1) % n) * n + (i + 1) % n;
      if (f < m.F.rows()) m.F.row(f++) << a, b, d;
      if (f < m.F.rows()) m.F.row(f++) << a, d, c;
    }
  return m;
}

TriMesh sphere(int rounds) {
  TriMesh octahedron;
  octahedron.V.resize(6, 3);
  octahedron.V << 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1, 0, 0, 0, 1, 0, 0, -1;
  octahedron.F.resize(8, 3);
  octahedron.F << 0, 2, 4, 2, 1, 4, 1, 3, 4, 3, 0, 4, 2, 0, 5, 1, 2, 5, 3, 1, 5, 0, 3, 5;
  TriMesh m = subdivide_midpoint(octahedron, rounds);
  m.V.rowwise().normalize();
  return m;
}

TriMesh annulus() {
  const TriMesh grid = grid_disk(4, 4);
  TriMesh m;
  m.V = grid.V;
  m.F.resize(grid.num_faces() - 2, 3);
  for (int f = 0, g = 0; f < grid.num_faces(); ++f)
    if (f / 2 != 4) m.F.row(g++) = grid.F.row(f);  // cell (1, 1) of 3x3 cells
  return m;
}

TriMesh side_by_side(const TriMesh& a, const TriMesh& b, double offset) {
  TriMesh m;
  m.V.resize(a.num_vertices() + b.num_vertices(), 3);
  m.V << a.V, b.V.rowwise() + Eigen::RowVector3d(offset, 0, 0);
  m.F.resize(a.num_faces() + b.num_faces(), 3);
  m.F << a.F, b.F.array() + a.num_vertices();
  return m;
}

TriMesh bumpy_disk(int nx, int ny) {
  TriMesh mesh = grid_disk(nx, ny);
  for (int v = 0; v < mesh.num_vertices(); ++v)
    mesh.V(v, 2) = 0.3 * std::sin(5 * mesh.V(v, 0)) * std::cos(4 * mesh.V(v, 1));
  return mesh;
}

TetMesh tet_grid(int n) {
  TetMesh mesh;
  const int m = n + 1;
  mesh.V.resize(m * m * m, 3);
  auto id = [&](int i, int j, int k) { return (k * m + j) * m + i; };
  for (int k = 0; k < m; ++k)
    for (int j = 0; j < m; ++j)
      for (int i = 0; i < m; ++i) mesh.V.row(id(i, j, k)) << double(i) / n, double(j) / n, double(k) / n;
  std::vector<Eigen::RowVector4i> tets;
  int order[3] = {0, 1, 2};
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        std::sort(order, order + 3);
        do {
          int c[3] = {i, j, k};
          Eigen::RowVector4i t;
          t[0] = id(c[0], c[1], c[2]);
          for (int s = 0; s < 3; ++s) {
            ++c[order[s]];
            t[s + 1] = id(c[0], c[1], c[2]);
          }
          tets.push_back(t);
        } while (std::next_permutation(order, order + 3));
      }
  mesh.T.resize(static_cast<Eigen::Index>(tets.size()), 4);
  for (std::size_t t = 0; t < tets.size(); ++t) mesh.T.row(t) = tets[t];
  for (int t = 0; t < mesh.num_tets(); ++t)
    if (signed_tet_volume(mesh, t) < 0) std::swap(mesh.T(t, 2), mesh.T(t, 3));
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

Eigen::VectorXd distorted_tet_positions(const TetMesh& mesh, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.03, 0.03);
  Eigen::MatrixXd P = mesh.V * Eigen::Vector3d(1.3, 0.9, 1.1).asDiagonal();
  for (int v = 0; v < P.rows(); ++v) P.row(v) += Eigen::RowVector3d(u(rng), u(rng), u(rng));
  Eigen::VectorXd x(3 * P.rows());
  for (int v = 0; v < P.rows(); ++v) x.segment<3>(3 * v) = P.row(v).transpose();
  return x;
}

int null_space_dimension(const Eigen::MatrixXd& K, bool* psd, double* gap) {
  const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig(K);
  const Eigen::VectorXd lambda = eig.eigenvalues();  // ascending
  const double tol = 1e-10 * lambda.maxCoeff();
  *psd = lambda.minCoeff() >= -tol;
  int dimension = 0;
  while (dimension < lambda.size() && lambda[dimension] < tol) ++dimension;
  *gap = dimension < lambda.size() ? lambda[dimension] / tol : 0;
  return dimension;
}

}  // namespace akvf::test
