#pragma once
// Line searches along a descent direction, always inside the flip-free
// region. The public search() is non-virtual: it checks the direction,
// computes the maximal feasible step and times the search, then calls the
// subclass's do_search().
#include <Eigen/Core>
#include <string>

#include "akvf/objective.h"

namespace akvf {

// Parameters shared by the line searches (each uses those that apply).
struct LineSearchSettings {
  // Sufficient decrease: E(x + a d) <= E(x) + c1 a grad^T d. Backtracking
  // also takes a point where E is not above E(x) and the slope is at most
  // (1 - 2 c1) |grad^T d| (approximate Wolfe): the first trial, or the
  // secant step after it where the decrease left is below round-off.
  double c1 = 1e-5;
  // Backtracking shrink factor. §5.3 of the paper states 0.9; the SLIM
  // framework the authors' code is built on halves the step, and halving
  // needs about half the iterations here, so 0.5 is
  // the default and --ls-rho 0.9 gives the paper's text.
  double rho = 0.5;
  double max_step_fraction = 0.8;  // alpha_0 <= fraction * alpha_max (flip-free bound)
  double max_initial_step = 1.0;   // alpha_0 <= this
  // The search fails when the step falls below min_step_ratio * alpha_0 or
  // after max_evaluations energy evaluations.
  double min_step_ratio = 1e-12;
  int max_evaluations = 400;
  // Backtracking: after a straight step that gained less than a quarter of
  // its linear prediction, also try the minimizer of the parabola through
  // E(x), grad E . d and that step, and keep the lower point.
  bool fit_parabola = true;

  bool is_valid(std::string* error) const;
};

struct LineSearchSummary {
  bool success = false;
  double step = 0;               // accepted alpha (0 on failure: x is unchanged)
  double max_feasible_step = 0;  // alpha_max of §5.3
  double initial_step = 0;
  // The first trial was max_step_fraction * alpha_max, below
  // max_initial_step (the direction's own step): the bound set it.
  bool bound_cut_initial_step = false;
  double energy = 0;    // E(x + step d), or E(x) on failure
  int evaluations = 0;  // energy evaluations
  double seconds = 0;
  std::string message;  // why it failed
  // The rotation-following term a (Objective::rotation_following_term) when
  // the accepted point is x + step d + (step^2 / 2) a; empty for a straight
  // step.
  Eigen::VectorXd turn;
  // grad E at the accepted point where the search evaluated it there with
  // the energy (Objective::value_and_gradient); empty otherwise.
  Eigen::VectorXd gradient;
};

// The point a search accepted: x + step d, plus (step^2 / 2) turn if any.
Eigen::VectorXd accepted_point(const Eigen::VectorXd& x, const Eigen::VectorXd& direction,
                               const LineSearchSummary& summary);
// The point at alpha along x + alpha d + (alpha^2 / 2) turn (turn empty:
// straight), written into *point.
void point_along_path(const Eigen::VectorXd& x, const Eigen::VectorXd& direction, const Eigen::VectorXd& turn,
                      double alpha, Eigen::VectorXd* point);

struct LineSearchInput {
  const Objective& objective;
  const Eigen::VectorXd& x;
  double energy;                    // E(x)
  const Eigen::VectorXd& gradient;  // grad E(x)
  const Eigen::VectorXd& direction;
  double directional_derivative;  // grad E(x) . d < 0
  double max_feasible_step;       // sup t with no element inverted
};

class LineSearch {
 public:
  virtual ~LineSearch() = default;
  virtual std::string name() const = 0;

  LineSearchSummary search(const Objective& objective, const Eigen::VectorXd& x, double energy,
                           const Eigen::VectorXd& gradient, const Eigen::VectorXd& direction) const;

 private:
  virtual LineSearchSummary do_search(const LineSearchInput& input) const = 0;
};

}  // namespace akvf
