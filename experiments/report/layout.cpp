#include "experiments/report/layout.h"

namespace akvf {

Layout layout_of(const ParamSetup& setup, const Eigen::VectorXd& x) {
  Layout layout;
  layout.excess = setup.objective->face_distortion(x).array() - setup.objective->density().lower_bound();
  layout.uv = chart_uv(setup, x);
  layout.F = setup.disk.mesh.F;
  return layout;
}

}  // namespace akvf
