// Parameterizes a curved grid built here and writes it as glTF and as an
// HTML view, through the public API alone.
#include <akvf/akvf.h>

#include <cmath>
#include <cstdio>
#include <filesystem>

int main(int argc, char** argv) {
  const int n = 12;
  Eigen::MatrixXd V(n * n, 3);
  Eigen::MatrixXi F(2 * (n - 1) * (n - 1), 3);
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double x = i / (n - 1.0), y = j / (n - 1.0);
      V.row(i * n + j) << x, y, 0.3 * std::sin(3 * x) * std::cos(2 * y);
    }
  int f = 0;
  for (int i = 0; i + 1 < n; ++i)
    for (int j = 0; j + 1 < n; ++j) {
      const int a = i * n + j, b = a + n, c = b + 1, d = a + 1;
      F.row(f++) << a, b, c;
      F.row(f++) << a, c, d;
    }
  const akvf::ParameterizeResult result = akvf::parameterize(V, F);
  std::printf("%s after %d iterations, energy %.6f\n", akvf::to_string(result.status).c_str(),
              result.statistics.iterations, result.energy());
  const std::filesystem::path out = argc > 1 ? argv[1] : ".";
  akvf::TriMesh mesh{V, F};
  akvf::write_mesh((out / "grid.glb").string(), mesh, result.uv, result.uv_faces);
  if (akvf::view_available()) {  // this build embeds three.js
    akvf::write_view((out / "grid.html").string(), mesh, result.uv, result.uv_faces, "grid");
    std::printf("view written\n");
  }
  return result.status == akvf::TerminationStatus::kConverged ? 0 : 1;
}
