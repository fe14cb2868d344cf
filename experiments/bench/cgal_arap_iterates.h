#pragma once
// CGAL's ARAP parameterizer run once more, writing its start and every
// iterate (CGAL's CGAL_SMP_ARAP_DEBUG output, the only way it shows them), to
// count their inverted triangles. Its own translation unit: the macro changes
// CGAL's code, so this run uses CGAL's Epick kernel, whose types (and so
// template instances) differ from the timed run's.
#include <Eigen/Core>
#include <string>

namespace akvf::bench {

struct ArapIterates {
  int iterations = 0;
  int initial_inverted = 0;
  int max_inverted = 0;  // over the iterates
  bool post_processed = false;
  std::string error;
};

ArapIterates count_arap_iterates(const Eigen::MatrixXd& V, const Eigen::MatrixXi& F);

}  // namespace akvf::bench
