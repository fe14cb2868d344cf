#include "experiments/report/layout.h"

namespace akvf {

Layout layout_of(const ParamSetup& setup, const Eigen::VectorXd& x) {
  Layout layout;
  layout.excess = setup.objective->face_distortion(x).array() - setup.objective->density().lower_bound();
  const Eigen::MatrixXd UV = output_uv(setup, x);
  const TriMesh& mesh = setup.disk.mesh;
  layout.uv.resize(mesh.num_vertices(), 2);
  for (int v = 0; v < mesh.num_vertices(); ++v) layout.uv.row(v) = UV.row(setup.disk.input_vertex[v]);
  layout.F = mesh.F;
  return layout;
}

}  // namespace akvf
