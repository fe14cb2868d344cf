#pragma once
// What the optimizer minimizes: a function of the stacked vertex positions x
// with a feasibility region (no inverted element) that line searches respect.
#include <Eigen/Core>
#include <cmath>
#include <limits>
#include <string>

namespace akvf {

// "<what> 7 of 72 is NaN" (or +inf, -inf) for the first non-finite entry of
// v, or "" when every entry is finite.
inline std::string first_non_finite_entry(const Eigen::VectorXd& v, const std::string& what) {
  for (Eigen::Index i = 0; i < v.size(); ++i)
    if (!std::isfinite(v[i]))
      return what + " " + std::to_string(i) + " of " + std::to_string(v.size()) + " is " +
             (std::isnan(v[i]) ? "NaN"
              : v[i] > 0       ? "+inf"
                               : "-inf");
  return "";
}

class Objective {
 public:
  virtual ~Objective() = default;

  virtual int num_variables() const = 0;
  // E(x); +infinity when an element is inverted.
  virtual double value(const Eigen::VectorXd& x) const = 0;
  // E(x) and its gradient (resized by the callee).
  virtual double value_and_gradient(const Eigen::VectorXd& x, Eigen::VectorXd* gradient) const = 0;
  // sup { t > 0 : no element of x + s d inverts for s in [0, t) }, +inf if
  // unbounded.
  virtual double max_feasible_step(const Eigen::VectorXd& x, const Eigen::VectorXd& d) const = 0;
  // Elements with det J <= 0 at x.
  virtual int count_inverted(const Eigen::VectorXd& x) const = 0;
  // The infimum of E, where known (4 for 2D symmetric Dirichlet).
  virtual double lower_bound() const { return -std::numeric_limits<double>::infinity(); }
  // What is wrong with x, for the message of a numerical failure: the first
  // bad element and why (non-finite coordinate, inverted, non-finite energy
  // or gradient), or "" when nothing is. This default names the first
  // non-finite variable.
  virtual std::string first_bad_element(const Eigen::VectorXd& x) const {
    return first_non_finite_entry(x, "variable");
  }
  // For a problem with positional constraints: the largest distance of a
  // constrained vertex from its target at x (how far the constraints are
  // from met; the trace's constraint_distance column). NaN without them.
  virtual double constraint_distance(const Eigen::VectorXd&) const { return std::numeric_limits<double>::quiet_NaN(); }
  // The second-order term a of the path x + t d + (t^2 / 2) a that follows
  // the turns of the elements d makes at x (the energies do not change under
  // a rotation, but a straight step along one stretches the element by
  // sqrt(1 + t^2 w^2)); false where the objective has none. The backtracking
  // line search tries that path where the straight trial fails.
  virtual bool rotation_following_term(const Eigen::VectorXd& /*x*/, const Eigen::VectorXd& /*d*/,
                                       Eigen::VectorXd* /*a*/) const {
    return false;
  }
};

}  // namespace akvf
