#pragma once
// The colour of a triangle's excess distortion D(J_f) - lower bound in the
// layout pictures (SVG and PNG): white (0) through orange to dark red
// (>= 10), on log10(1 + excess); non-finite is dark red.
#include <algorithm>
#include <array>
#include <cmath>

namespace akvf {

inline std::array<unsigned char, 3> distortion_color(double excess) {
  const double t =
      std::isfinite(excess) ? std::clamp(std::log10(1 + std::max(excess, 0.0)) / std::log10(11.0), 0.0, 1.0) : 1.0;
  return {static_cast<unsigned char>(255 - 115 * t * t), static_cast<unsigned char>(255 * (1 - t)),
          static_cast<unsigned char>(255 * (1 - t) * (1 - t))};
}

}  // namespace akvf
