#include "framework/mesh/unusable_faces.h"

#include <Eigen/Geometry>
#include <algorithm>
#include <map>

namespace akvf {

bool zero_area_face(const TriMesh& mesh, int f) {
  const Eigen::Vector3d a = mesh.V.row(mesh.F(f, 0)), b = mesh.V.row(mesh.F(f, 1)), c = mesh.V.row(mesh.F(f, 2));
  const double area = 0.5 * (b - a).cross(c - a).norm();
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  return !(area > 1e-14 * longest * longest);
}

UnusableFaces find_unusable_faces(const TriMesh& mesh) {
  UnusableFaces result;
  std::map<std::array<int, 3>, int> seen;
  for (int f = 0; f < mesh.num_faces(); ++f) {
    std::array<int, 3> corners = {mesh.F(f, 0), mesh.F(f, 1), mesh.F(f, 2)};
    std::sort(corners.begin(), corners.end());
    bool removed = true;
    if (corners[0] == corners[1] || corners[1] == corners[2])
      ++result.repeated_vertex;
    else if (zero_area_face(mesh, f))
      ++result.zero_area;
    else if (!seen.emplace(corners, f).second)
      ++result.repeated_face;
    else
      removed = false;
    (removed ? result.removed : result.kept).push_back(f);
  }
  return result;
}

std::vector<std::array<CornerSource, 3>> corner_sources(const TriMesh& input, const std::vector<int>& removed,
                                                        const std::vector<int>& input_vertex) {
  std::vector<int> parameterized(input.num_vertices(), -1);
  for (int v = static_cast<int>(input_vertex.size()) - 1; v >= 0; --v) parameterized[input_vertex[v]] = v;
  std::vector<std::array<CornerSource, 3>> sources(removed.size());
  for (std::size_t i = 0; i < removed.size(); ++i) {
    const int f = removed[i];
    for (int k = 0; k < 3; ++k) {
      CornerSource& source = sources[i][k];
      const int own = parameterized[input.F(f, k)];
      if (own >= 0) {
        source = {own, own, 0.0};
        continue;
      }
      const int u = input.F(f, (k + 1) % 3), w = input.F(f, (k + 2) % 3);
      const int pu = parameterized[u], pw = parameterized[w];
      if (pu >= 0 && pw >= 0 && pu != pw) {
        const Eigen::Vector3d p = input.V.row(input.F(f, k)), from = input.V.row(u), to = input.V.row(w);
        const double length2 = (to - from).squaredNorm();
        const double t = length2 > 0 ? std::clamp((p - from).dot(to - from) / length2, 0.0, 1.0) : 0.0;
        source = {pu, pw, t};
      } else if (pu >= 0 || pw >= 0) {
        const int near = pu >= 0 ? pu : pw;
        source = {near, near, 0.0};
      }
    }
  }
  return sources;
}

}  // namespace akvf
