#pragma once
// What a picture of a UV layout draws (SVG and PNG alike): the map at x on
// the compacted mesh at the input's scale, its faces, and each face's excess
// distortion D(J_f) - lower bound; and the content of its HTML view.
#include <Eigen/Core>

#include "akvf/internal/parameterization.h"
#include "pictures/html_view.h"

namespace akvf {

struct Layout {
  Eigen::MatrixXd uv;      // #V (compacted) by 2
  Eigen::MatrixXi F;       // #F by 3
  Eigen::VectorXd excess;  // #F
};

Layout layout_of(const ParamSetup& setup, const Eigen::VectorXd& x);

// The HTML view of the map at x (html_view.h): the optimized (compacted,
// cut) mesh with its chart UVs; the caller adds a summary if it has one.
ViewContent view_of(const ParamSetup& setup, const Eigen::VectorXd& x, const std::string& title);

}  // namespace akvf
