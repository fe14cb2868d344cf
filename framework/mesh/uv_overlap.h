#pragma once
// How much of a UV map lies over itself: each chart's triangles are
// rasterized on a grid of sample points over the chart's bounding box, and
// a sample covered by two or more triangles of the chart is overlapped.
// Charts are measured one by one (they are packed apart afterwards).
#include <Eigen/Core>
#include <vector>

namespace akvf {

struct UvOverlap {
  long long covered_samples = 0;     // samples inside at least one triangle
  long long overlapped_samples = 0;  // samples inside two or more triangles of one chart
  // overlapped / covered: about the fraction of the map's area lying over
  // another part of it; 0 for an injective map.
  double fraction() const {
    return covered_samples > 0 ? static_cast<double>(overlapped_samples) / covered_samples : 0.0;
  }
};

//   UV          #V by 2
//   F           #F by 3
//   face_chart  #F: chart of each face (empty = one chart)
//   samples     the grid's sample count over all charts, shared by their
//               areas (at least 1024 per chart); a sample is inside a
//               triangle only strictly, so triangles sharing an edge never
//               count as overlapping.
UvOverlap measure_uv_overlap(const Eigen::MatrixXd& UV, const Eigen::MatrixXi& F, const std::vector<int>& face_chart,
                             long long samples = 1 << 20);

}  // namespace akvf
