#include "akvf/internal/demo_mesh.h"

#include <cmath>

namespace akvf {

TriMesh bent_bar(int nx, int ny, double length, double width, double bend_angle) {
  TriMesh mesh;
  mesh.V.resize(nx * ny, 3);
  const double radius = length / bend_angle;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const double s = length * i / (nx - 1), t = width * j / (ny - 1);
      const double phi = s / radius;  // arc length s on a circle of this radius
      mesh.V.row(j * nx + i) << radius * std::sin(phi), radius * (1 - std::cos(phi)), t;
    }
  mesh.F.resize(2 * (nx - 1) * (ny - 1), 3);
  int f = 0;
  for (int j = 0; j + 1 < ny; ++j)
    for (int i = 0; i + 1 < nx; ++i) {
      const int a = j * nx + i, b = a + 1, c = a + nx, d = c + 1;
      if ((i + j) % 2 == 0) {
        mesh.F.row(f++) << a, b, d;
        mesh.F.row(f++) << a, d, c;
      } else {
        mesh.F.row(f++) << a, b, c;
        mesh.F.row(f++) << b, d, c;
      }
    }
  return mesh;
}

}  // namespace akvf
