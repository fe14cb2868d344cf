#pragma once
// SVG picture of a UV layout: every triangle filled by its distortion
// D(J_f) - lower bound on a log scale (white = isometric, dark red = 10+),
// with the boundary-free wireframe drawn thin.
#include <string>

#include <Eigen/Core>

#include "akvf/internal/parameterization.h"

namespace akvf {

//   UV          #V by 2
//   F           #F by 3
//   distortion  #F per-face excess distortion D(J_f) - lower bound (>= 0)
void write_uv_svg(const std::string& path, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F,
                  const Eigen::VectorXd& distortion, const std::string& title);

// The UV layout of a parameterization at x (area-1 units) as SVG, triangles
// shaded by D(J_f) - lower bound, at the input's scale.
void write_layout_svg(const std::string& path, const ParamSetup& setup, const Eigen::VectorXd& x,
                      const std::string& title);

}  // namespace akvf
