#pragma once
// The UV layout as a PNG of any size: every triangle filled by its
// distortion like the SVG (distortion_color.h), antialiased by 4 x 4
// supersampling, on white, with a margin. For meshes whose SVG is too large
// to view (the experiment runner switches to it above a face count).
#include <string>

#include <Eigen/Core>

#include "akvf/internal/parameterization.h"

namespace akvf {

//   UV  #V by 2; F #F by 3; distortion #F excess D(J_f) - lower bound
//   size  the longer side in pixels
void write_uv_png(const std::string& path, const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F,
                  const Eigen::VectorXd& distortion, int size);

// The layout of a parameterization at x (as write_layout_svg).
void write_layout_png(const std::string& path, const ParamSetup& setup, const Eigen::VectorXd& x, int size);

}  // namespace akvf
