#include "akvf/internal/slim_cube.h"

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>

#include "akvf/error.h"

namespace akvf {

PositionConstraints slim_cube_constraints(const TetMesh& mesh) {
  const Eigen::RowVector3d lo = mesh.V.colwise().minCoeff(), hi = mesh.V.colwise().maxCoeff();
  const double tolerance = 1e-9 * (hi - lo).norm();
  const Eigen::Vector3d axis = Eigen::Vector3d(1, 1, 0).normalized();
  // Each of the four vertical edges: which x and y bound it sits on, and its transform.
  struct Edge {
    bool max_x, max_y;
  };
  const Edge edges[4] = {{false, false}, {true, true}, {false, true}, {true, false}};
  PositionConstraints constraints;
  std::vector<Eigen::RowVector3d> targets;
  for (const Edge& edge : edges) {
    const double x = edge.max_x ? hi.x() : lo.x(), y = edge.max_y ? hi.y() : lo.y();
    const Eigen::Vector3d midpoint(x, y, 0.5 * (lo.z() + hi.z()));
    for (int v = 0; v < mesh.num_vertices(); ++v) {
      if (std::abs(mesh.V(v, 0) - x) > tolerance || std::abs(mesh.V(v, 1) - y) > tolerance) continue;
      const Eigen::Vector3d p = mesh.V.row(v).transpose();
      Eigen::Vector3d target;
      if (!edge.max_x && !edge.max_y)
        target = midpoint + Eigen::AngleAxisd(0.3 * std::numbers::pi, axis) * (p - midpoint);
      else if (edge.max_x && edge.max_y)
        target = midpoint + Eigen::AngleAxisd(-0.3 * std::numbers::pi, axis) * (p - midpoint);
      else
        target = 0.75 * p;
      constraints.vertices.push_back(v);
      targets.push_back(target.transpose());
    }
  }
  if (constraints.vertices.empty())
    throw ValidationError("the slim-cube preset found no vertices on the mesh's vertical edges");
  constraints.targets.resize(static_cast<Eigen::Index>(targets.size()), 3);
  for (std::size_t c = 0; c < targets.size(); ++c) constraints.targets.row(c) = targets[c];
  return constraints;
}

}  // namespace akvf
