// Parameterize a triangle mesh with the library's defaults: a curved grid
// built here, or the OBJ/OFF file given as the first argument.
#include <akvf/akvf.h>

#include <cmath>
#include <iostream>

namespace {

// An n x n grid of the unit square bent onto a bump (a disk that is not
// developable). V #V by 3, F #F by 3, 0-based.
void curved_grid(int n, Eigen::MatrixXd* V, Eigen::MatrixXi* F) {
  V->resize(n * n, 3);
  F->resize(2 * (n - 1) * (n - 1), 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = double(i) / (n - 1), y = double(j) / (n - 1);
      V->row(j * n + i) << x, y, 0.3 * std::sin(3 * x) * std::cos(2 * y);
    }
  int f = 0;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i, b = a + 1, c = a + n, d = c + 1;
      F->row(f++) << a, b, d;
      F->row(f++) << a, d, c;
    }
}

// Triangles of the UV map with non-positive signed area.
int inverted(const Eigen::MatrixXd& uv, const Eigen::MatrixXi& F) {
  int count = 0;
  for (int f = 0; f < F.rows(); ++f) {
    const Eigen::RowVector2d e1 = uv.row(F(f, 1)) - uv.row(F(f, 0)), e2 = uv.row(F(f, 2)) - uv.row(F(f, 0));
    count += !(e1.x() * e2.y() - e1.y() * e2.x() > 0);
  }
  return count;
}

}  // namespace

int main(int argc, char** argv) try {
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  if (argc > 1) {
    const akvf::TriMesh mesh = akvf::read_triangle_mesh(argv[1]);
    V = mesh.V;
    F = mesh.F;
  } else {
    curved_grid(20, &V, &F);
  }
  const akvf::ParameterizeResult result = akvf::parameterize(V, F);
  std::cout << "akvf " << akvf::kVersion << ": " << akvf::to_string(result.status) << " after " << result.iterations()
            << " iterations, energy " << result.energy() << ", " << result.statistics.preconditioner.factorizations
            << " factorizations; uv " << result.uv.rows() << " x " << result.uv.cols() << ", " << inverted(result.uv, F)
            << " inverted\n";
  const bool ok = result.status == akvf::TerminationStatus::kConverged && result.uv.rows() == V.rows() &&
                  result.uv.cols() == 2 && inverted(result.uv, F) == 0;
  return ok ? 0 : 1;
} catch (const akvf::Error& e) {
  std::cerr << "error: " << e.what() << '\n';
  return 1;
}
