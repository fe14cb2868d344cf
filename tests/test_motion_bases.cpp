// ComponentMotions::project_out: the motions removed, with the bits of
// Eigen's `v -= B * (B.transpose() * v)` per basis block.
#include <doctest/doctest.h>

#include <algorithm>
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

namespace {

// c g g^T of one barrier-like term on three vertices of x (2D), added to
// the dense symmetric C.
void add_term(const int (&vertex)[3], const Eigen::Vector2d (&gradient)[3], Eigen::MatrixXd* C) {
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b)
      C->block<2, 2>(2 * vertex[a], 2 * vertex[b]) += 0.7 * gradient[a] * gradient[b].transpose();
}

Eigen::Vector2d at(const Eigen::VectorXd& x, int v) { return x.segment<2>(2 * v); }

// The inner angle at vertex 1 between 0 and 2: invariant under similarities.
void add_angle_term(const Eigen::VectorXd& x, const int (&v)[3], Eigen::MatrixXd* C) {
  const Eigen::Vector2d u = at(x, v[2]) - at(x, v[1]), w = at(x, v[0]) - at(x, v[1]);
  const Eigen::Vector2d d_next(-u.y() / u.squaredNorm(), u.x() / u.squaredNorm());
  const Eigen::Vector2d d_previous(w.y() / w.squaredNorm(), -w.x() / w.squaredNorm());
  add_term(v, {d_previous, -(d_next + d_previous), d_next}, C);
}

// The distance of vertex 0 from the segment 1 2: invariant under rigid
// motions only.
void add_distance_term(const Eigen::VectorXd& x, const int (&v)[3], Eigen::MatrixXd* C) {
  const Eigen::Vector2d p = at(x, v[0]), a = at(x, v[1]), b = at(x, v[2]);
  const double s = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
  const Eigen::Vector2d n = (p - (a + s * (b - a))).normalized();
  add_term(v, {n, -(1 - s) * n, -s * n}, C);
}

Eigen::SparseMatrix<double> upper(const Eigen::MatrixXd& C) {
  const Eigen::MatrixXd triangle = C.triangularView<Eigen::Upper>();
  return triangle.sparseView();
}

}  // namespace

TEST_CASE(
    "the motions C does not stiffen: a scale-invariant term keeps the similarities, a distance drops the dilation") {
  const int n = 9;
  Eigen::VectorXd x(2 * n);
  for (int i = 0; i < n; ++i) x.segment<2>(2 * i) << std::cos(0.7 * i) * (1 + 0.1 * i), std::sin(0.7 * i);
  const Eigen::MatrixXd similarities = akvf::similarity_motion_basis_2d(x);
  const Eigen::VectorXd v = wavy(2 * n, 0.3);

  // Angles only: every similarity stays, the basis bit for bit.
  Eigen::MatrixXd C = Eigen::MatrixXd::Zero(2 * n, 2 * n);
  add_angle_term(x, {1, 2, 3}, &C);
  add_angle_term(x, {5, 6, 7}, &C);
  REQUIRE((C * similarities).norm() <= 1e-12 * C.norm());
  akvf::ComponentMotions kept(similarities), all(similarities);
  kept.keep_unstiffened_by(upper(C));
  Eigen::VectorXd a = v, b = v;
  kept.project_out(&a);
  all.project_out(&b);
  CHECK(same_bits(a, b));

  // A distance too: the dilation goes, the rigid motions stay.
  add_distance_term(x, {0, 4, 5}, &C);
  akvf::ComponentMotions rigid_only(similarities);
  rigid_only.keep_unstiffened_by(upper(C));
  Eigen::VectorXd projected = v, expected = v;
  rigid_only.project_out(&projected);
  const Eigen::MatrixXd rigid = akvf::rigid_motion_basis_2d(x);
  expected -= rigid * (rigid.transpose() * expected);
  CHECK((projected - expected).norm() <= 1e-10 * v.norm());

  // Per component: only the component the distance term acts on loses it.
  auto components = std::make_shared<const std::vector<std::vector<int>>>(
      std::vector<std::vector<int>>{{0, 1, 2, 3, 4, 5, 6, 7, 8}, {9, 10, 11}});
  Eigen::VectorXd x2(2 * 12);
  x2 << x, 5, 0, 6, 0.5, 5.5, 1;
  akvf::ComponentMotions blocks(2, components, x2, akvf::similarity_motion_basis_2d);
  Eigen::MatrixXd C2 = Eigen::MatrixXd::Zero(24, 24);
  C2.topLeftCorner(2 * n, 2 * n) = C;
  blocks.keep_unstiffened_by(upper(C2));
  Eigen::VectorXd w = wavy(24, 1.1), w_expected = w;
  blocks.project_out(&w);
  w_expected.head(2 * n) -= rigid * (rigid.transpose() * w_expected.head(2 * n));
  const Eigen::MatrixXd second = akvf::similarity_motion_basis_2d(x2.tail(6));
  w_expected.tail(6) -= second * (second.transpose() * w_expected.tail(6));
  CHECK((w - w_expected).norm() <= 1e-10 * w.norm());
}
