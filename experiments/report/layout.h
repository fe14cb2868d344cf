#pragma once
// What a picture of a UV layout draws (SVG and PNG alike): the map at x on
// the compacted mesh at the input's scale, its faces, and each face's excess
// distortion D(J_f) - lower bound.
#include <Eigen/Core>

#include "akvf/parameterization.h"

namespace akvf {

struct Layout {
  Eigen::MatrixXd uv;      // #V (compacted) by 2
  Eigen::MatrixXi F;       // #F by 3
  Eigen::VectorXd excess;  // #F
};

Layout layout_of(const ParamSetup& setup, const Eigen::VectorXd& x);

}  // namespace akvf
