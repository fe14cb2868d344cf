#pragma once
// Positional constraints: vertices and the positions they should reach
// (read by constraints_io.h, used by constrained_objective.h).
#include <Eigen/Core>
#include <vector>

namespace akvf {

struct PositionConstraints {
  std::vector<int> vertices;  // constrained vertex indices (0-based)
  Eigen::MatrixXd targets;    // #C by D target positions p_i
};

}  // namespace akvf
