#include "preconditioners/contact_curvature.h"

#include <Eigen/Eigenvalues>
#include <algorithm>

namespace akvf {

namespace {
// H with its negative eigenvalues clamped to 0.
Eigen::Matrix<double, 6, 6> projected(const Eigen::Matrix<double, 6, 6>& H) {
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix<double, 6, 6>> eigen(H);
  return eigen.eigenvectors() * eigen.eigenvalues().cwiseMax(0.0).asDiagonal() * eigen.eigenvectors().transpose();
}
}  // namespace

ContactCurvature::ContactCurvature(std::shared_ptr<const BoundaryContact> contact, int num_vertices)
    : contact_(std::move(contact)), num_vertices_(num_vertices), matrix_(2 * num_vertices, 2 * num_vertices) {}

const Eigen::SparseMatrix<double>& ContactCurvature::at(const Eigen::VectorXd& x, ContactModel model) {
  const std::vector<BoundaryContact::ActiveTerm> terms = contact_->active_terms(x);
  const auto n = static_cast<std::uint64_t>(num_vertices_);
  const auto add_pairs = [&](const int* vertex) {
    bool added = false;
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const auto i = static_cast<std::uint64_t>(vertex[a]), j = static_cast<std::uint64_t>(vertex[b]);
        if (i <= j && pairs_.insert(i * n + j).second) {
          sorted_pairs_.push_back(i * n + j);
          added = true;
        }
      }
    return added;
  };
  bool grown = false;
  for (const BoundaryContact::ActiveTerm& term : terms) grown = add_pairs(term.vertex) || grown;
  // A pattern that has to grow takes the terms within twice their reach as
  // well; one whose pairs are mostly out of that reach is rebuilt from them
  // (module comment). The terms within the margin cost a query as large as
  // the active ones', so they are looked for only when the active terms
  // (at most 6 pairs each) couple under a quarter of a quarter of the
  // pattern: where more are active, the margin's, which include them,
  // rarely fall under a quarter (cow_b: at 32 of 46 iterations without this).
  if (grown) {
    for (const std::array<int, 3>& vertex : contact_->terms_within(x, kProspectiveReach)) add_pairs(vertex.data());
  } else if (6 * terms.size() < sorted_pairs_.size() / (kShrinkRatio * kShrinkRatio)) {
    const std::vector<std::array<int, 3>> near = contact_->terms_within(x, kProspectiveReach);
    if (6 * near.size() < sorted_pairs_.size() / kShrinkRatio) {
      pairs_.clear();
      sorted_pairs_.clear();
      for (const std::array<int, 3>& vertex : near) add_pairs(vertex.data());
      grown = true;
    }
  }
  if (grown) {
    std::sort(sorted_pairs_.begin(), sorted_pairs_.end());
    ++version_;
    build_pattern();
  }
  // The values: zero on the pattern, then each term's blocks added in the
  // terms' order.
  double* values = matrix_.valuePtr();
  std::fill(values, values + matrix_.nonZeros(), 0.0);
  const bool whole = model != ContactModel::kGaussNewton;
  for (const BoundaryContact::ActiveTerm& term : terms) {
    Eigen::Matrix<double, 6, 6> hessian = Eigen::Matrix<double, 6, 6>::Zero();
    if (whole) hessian = BoundaryContact::hessian(term, x);
    if (model == ContactModel::kProjectedHessian) hessian = projected(hessian);
    for (int a = 0; a < 3; ++a)
      for (int b = 0; b < 3; ++b) {
        const int i = term.vertex[a], j = term.vertex[b];
        if (i > j) continue;
        const Eigen::Matrix2d block =
            whole ? Eigen::Matrix2d(hessian.block<2, 2>(2 * a, 2 * b))
                  : Eigen::Matrix2d(term.curvature * term.gradient[a] * term.gradient[b].transpose());
        for (int r = 0; r < 2; ++r)
          for (int c = 0; c < 2; ++c)
            if (i != j || r <= c) values[entry(2 * i + r, 2 * j + c)] += block(r, c);
      }
  }
  return matrix_;
}

void ContactCurvature::build_pattern() {
  // Each pair's 2 x 2 block (the upper triangle of a diagonal one), columns
  // compressed, rows increasing within each column.
  const auto n = static_cast<std::uint64_t>(num_vertices_);
  std::vector<Eigen::Triplet<double>> entries;
  entries.reserve(4 * sorted_pairs_.size());
  for (const std::uint64_t pair : sorted_pairs_) {
    const auto i = static_cast<int>(pair / n), j = static_cast<int>(pair % n);
    for (int r = 0; r < 2; ++r)
      for (int c = 0; c < 2; ++c)
        if (i != j || r <= c) entries.emplace_back(2 * i + r, 2 * j + c, 0.0);
  }
  matrix_.setFromTriplets(entries.begin(), entries.end());
  matrix_.makeCompressed();
}

int ContactCurvature::entry(int row, int column) const {
  const int* rows = matrix_.innerIndexPtr();
  const int* first = rows + matrix_.outerIndexPtr()[column];
  const int* last = rows + matrix_.outerIndexPtr()[column + 1];
  return static_cast<int>(std::lower_bound(first, last, row) - rows);
}

}  // namespace akvf
