#include "framework/optimization/local_newton_sweep.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>

#include <Eigen/Cholesky>
#include <algorithm>
#include <cmath>
#include <limits>

#include "framework/optimization/element_derivatives.h"

namespace akvf {

namespace {

// The share of the flip-free bound a step may take: the global line
// search's first trial (line_search.h, max_step_fraction).
constexpr double kBoundShare = 0.8;
constexpr double kSufficientDecrease = 1e-4;
constexpr int kMaxHalvings = 20;

}  // namespace

template <int D>
LocalNewtonSweep<D>::LocalNewtonSweep(const MeshObjective<D>& objective, const std::vector<int>& fixed)
    : objective_(objective) {
  const Eigen::MatrixXi& elements = objective.elements();
  const int n = objective.num_vertices();
  incidence_start_.assign(n + 1, 0);
  for (int e = 0; e < elements.rows(); ++e)
    for (int a = 0; a <= D; ++a) ++incidence_start_[elements(e, a) + 1];
  for (int v = 0; v < n; ++v) incidence_start_[v + 1] += incidence_start_[v];
  incidence_.resize(incidence_start_[n]);
  std::vector<int> fill(incidence_start_.begin(), incidence_start_.end() - 1);
  for (int e = 0; e < elements.rows(); ++e)
    for (int a = 0; a <= D; ++a) incidence_[fill[elements(e, a)]++] = e * (D + 1) + a;

  // Greedy colouring in vertex order: the least colour no vertex sharing an
  // element has taken.
  std::vector<int> colour(n, -1), seen_by;
  int colours = 0;
  for (int v = 0; v < n; ++v) {
    for (int p = incidence_start_[v]; p < incidence_start_[v + 1]; ++p) {
      const int e = incidence_[p] / (D + 1);
      for (int b = 0; b <= D; ++b)
        if (const int c = colour[elements(e, b)]; c >= 0) seen_by[c] = v;
    }
    int c = 0;
    while (c < colours && seen_by[c] == v) ++c;
    if (c == colours) {
      ++colours;
      seen_by.push_back(-1);
    }
    colour[v] = c;
  }
  for (int v : fixed) colour[v] = -1;
  colour_start_.assign(colours + 1, 0);
  for (int v = 0; v < n; ++v)
    if (colour[v] >= 0) ++colour_start_[colour[v] + 1];
  for (int c = 0; c < colours; ++c) colour_start_[c + 1] += colour_start_[c];
  by_colour_.resize(colour_start_[colours]);
  fill.assign(colour_start_.begin(), colour_start_.end() - 1);
  for (int v = 0; v < n; ++v)
    if (colour[v] >= 0) by_colour_[fill[colour[v]]++] = v;
}

template <int D>
bool LocalNewtonSweep<D>::move_vertex(int v, Eigen::VectorXd* x) const {
  using Matrix = Eigen::Matrix<double, D, D>;
  using Vector = Eigen::Matrix<double, D, 1>;
  const auto& density = objective_.density();
  const auto& weights = objective_.weights();
  const auto& rest = objective_.rest();
  const int first = incidence_start_[v], last = incidence_start_[v + 1];

  // E_v, its gradient and projected Hessian in v's position. With h the
  // rest gradient of v's hat function on element e, J_e changes by dy h^T
  // when v moves by dy.
  auto hat = [&](int p) { return hat_gradients<D>(rest.Dm_inv[incidence_[p] / (D + 1)])[incidence_[p] % (D + 1)]; };
  double energy = 0;
  Vector gradient = Vector::Zero();
  Matrix hessian = Matrix::Zero();
  for (int p = first; p < last; ++p) {
    const int e = incidence_[p] / (D + 1);
    const Vector h = hat(p);
    const Matrix J = objective_.jacobian(*x, e);
    Matrix dJ;
    energy += weights[e] * density.value_and_gradient(J, &dJ);
    gradient += weights[e] * dJ * h;
    // d vec(J) / dy = h (x) I: the (r, s) entry of the block is
    // sum_{c, c'} h_c h_c' H(r + D c, s + D c').
    const auto H = density.projected_hessian(J);
    for (int c = 0; c < D; ++c)
      for (int c2 = 0; c2 < D; ++c2) hessian += weights[e] * h[c] * h[c2] * H.template block<D, D>(D * c, D * c2);
  }
  if (!(gradient.squaredNorm() > 0) || !std::isfinite(energy)) return false;
  const Eigen::LDLT<Matrix> ldlt(hessian);
  const Vector step = -ldlt.solve(gradient);
  const double slope = gradient.dot(step);
  if (!step.allFinite() || !(slope < 0)) return false;

  // det J_e is linear along the step: det(J + t step h^T) = det J (1 + t h^T J^-1 step).
  double bound = std::numeric_limits<double>::infinity();
  for (int p = first; p < last; ++p) {
    const double rate = hat(p).dot(objective_.jacobian(*x, incidence_[p] / (D + 1)).inverse() * step);
    if (rate < 0) bound = std::min(bound, -1 / rate);
  }
  // A step the bound would cut has its model's minimizer past a collapse:
  // the model misses what holds the vertex (a clamped Hessian), and taking
  // the cut step would compress an element toward the collapse the sweep
  // is meant to relieve.
  if (kBoundShare * bound < 1) return false;
  double t = 1;
  const Vector start = x->template segment<D>(D * v);
  for (int halving = 0; halving <= kMaxHalvings; ++halving, t *= 0.5) {
    x->template segment<D>(D * v) = start + t * step;
    double trial = 0;
    for (int p = first; p < last && std::isfinite(trial); ++p) {
      const int e = incidence_[p] / (D + 1);
      const Matrix J = objective_.jacobian(*x, e);
      trial = J.determinant() > 0 ? trial + weights[e] * density.value(J) : std::numeric_limits<double>::infinity();
    }
    if (trial <= energy + kSufficientDecrease * t * slope) return true;
  }
  x->template segment<D>(D * v) = start;
  return false;
}

template <int D>
int LocalNewtonSweep<D>::sweep(const Eigen::VectorXd& gradient, double gradient_share, Eigen::VectorXd* x) const {
  const int n = objective_.num_vertices();
  const double threshold = gradient_share * gradient.squaredNorm() / n;
  int moved = 0;
  std::vector<int> chosen;
  std::vector<char> did_move;
  for (int c = 0; c + 1 < static_cast<int>(colour_start_.size()); ++c) {
    chosen.clear();
    for (int i = colour_start_[c]; i < colour_start_[c + 1]; ++i)
      if (const int v = by_colour_[i]; gradient.template segment<D>(D * v).squaredNorm() > threshold)
        chosen.push_back(v);
    did_move.assign(chosen.size(), 0);
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chosen.size(), 64),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t i = r.begin(); i != r.end(); ++i) did_move[i] = move_vertex(chosen[i], x);
                      });
    moved += static_cast<int>(std::count(did_move.begin(), did_move.end(), 1));
  }
  return moved;
}

template class LocalNewtonSweep<2>;
template class LocalNewtonSweep<3>;

}  // namespace akvf
