// ComponentMotions::project_out: the motions removed, with the bits of
// Eigen's `v -= B * (B.transpose() * v)` per basis block.
#include <doctest/doctest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <vector>

#include "akvf/motion_bases.h"

namespace {

Eigen::VectorXd wavy(Eigen::Index n, double phase) {
  Eigen::VectorXd v(n);
  for (Eigen::Index i = 0; i < n; ++i)
    v[i] = std::sin(phase + 1.3 * static_cast<double>(i)) * std::pow(10.0, static_cast<double>(i % 5) - 2);
  for (Eigen::Index i = 3; i < n; i += 13) v[i] = -0.0;
  return v;
}

bool same_bits(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), sizeof(double) * a.size()) == 0;
}

}  // namespace

TEST_CASE("projecting out motions gives Eigen's bits for every basis, whole or per component") {
  for (const Eigen::Index vertices : {Eigen::Index{1}, Eigen::Index{7}, Eigen::Index{1001}}) {
    CAPTURE(vertices);
    const Eigen::VectorXd x2 = wavy(2 * vertices, 0.4), x3 = wavy(3 * vertices, 0.9);
    const std::vector<Eigen::MatrixXd> bases = {akvf::rigid_motion_basis_2d(x2), akvf::similarity_motion_basis_2d(x2),
                                                akvf::translation_basis(2, vertices), akvf::rigid_motion_basis_3d(x3),
                                                akvf::translation_basis(3, vertices)};
    for (const Eigen::MatrixXd& B : bases) {
      CAPTURE(B.cols());
      const Eigen::VectorXd v = wavy(B.rows(), 2.1);
      Eigen::VectorXd expected = v;
      expected -= B * (B.transpose() * expected);
      Eigen::VectorXd projected = v;
      akvf::ComponentMotions(B).project_out(&projected);
      CHECK(same_bits(projected, expected));
    }
  }
  // Two components, vertices interleaved: each block acts on its own vertices.
  const auto components =
      std::make_shared<std::vector<std::vector<int>>>(std::vector<std::vector<int>>{{0, 2, 4, 6, 8}, {1, 3, 5, 7}});
  const Eigen::VectorXd x = wavy(18, 0.2);
  const akvf::ComponentMotions motions(2, components, x,
                                       [](const Eigen::VectorXd& part) { return akvf::rigid_motion_basis_2d(part); });
  const Eigen::VectorXd v = wavy(18, 1.7);
  Eigen::VectorXd expected = v;
  for (const std::vector<int>& vertices : *components) {
    Eigen::VectorXd part_x(2 * vertices.size()), part(2 * vertices.size());
    for (std::size_t i = 0; i < vertices.size(); ++i) {
      part_x.segment<2>(2 * i) = x.segment<2>(2 * vertices[i]);
      part.segment<2>(2 * i) = v.segment<2>(2 * vertices[i]);
    }
    const Eigen::MatrixXd B = akvf::rigid_motion_basis_2d(part_x);
    part -= B * (B.transpose() * part);
    for (std::size_t i = 0; i < vertices.size(); ++i) expected.segment<2>(2 * vertices[i]) = part.segment<2>(2 * i);
  }
  Eigen::VectorXd projected = v;
  motions.project_out(&projected);
  CHECK(same_bits(projected, expected));
}
