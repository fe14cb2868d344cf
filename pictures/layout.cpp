#include "pictures/layout.h"

namespace akvf {

Layout layout_of(const ParamSetup& setup, const Eigen::VectorXd& x) {
  Layout layout;
  layout.excess = setup.objective->face_distortion(x).array() - setup.objective->density().lower_bound();
  layout.uv = chart_uv(setup, x);
  layout.F = setup.disk.mesh.F;
  return layout;
}

ViewContent view_of(const ParamSetup& setup, const Eigen::VectorXd& x, const std::string& title) {
  ViewContent view;
  view.mesh = setup.disk.mesh;
  view.uv = chart_uv(setup, x);
  view.uv_faces = setup.disk.mesh.F;
  view.title = title;
  return view;
}

}  // namespace akvf
