// A user-defined energy, written only as its density D(J): the symmetric
// Dirichlet energy plus a penalty on the log of the area change. The library
// differentiates it (gradient, Hessian, PSD projection, dD/dsigma for SLIM);
// registered by name, it runs with every preconditioner.
#include <akvf/akvf.h>

#include <cmath>
#include <iostream>

namespace {

struct AreaAwareDirichlet {
  double area_weight = 0.5;
  // Called with det J > 0 only; T is double or a dual number.
  template <class T>
  T operator()(const Eigen::Matrix<T, 2, 2>& J) const {
    using std::log;  // ceres::log / Eigen's for dual numbers, found by argument-dependent lookup
    const T det = J.determinant();
    const T symmetric_dirichlet = J.squaredNorm() * (T(1.0) + T(1.0) / (det * det));  // |J|^2 + |J^-1|^2
    const T log_area = log(det);
    return symmetric_dirichlet + T(area_weight) * log_area * log_area;
  }
};

void bumpy_grid(int n, Eigen::MatrixXd* V, Eigen::MatrixXi* F) {
  V->resize(n * n, 3);
  F->resize(2 * (n - 1) * (n - 1), 3);
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const double x = double(i) / (n - 1), y = double(j) / (n - 1);
      V->row(j * n + i) << x, y, 0.25 * std::sin(4 * x) * std::sin(3 * y);
    }
  int f = 0;
  for (int j = 0; j + 1 < n; ++j)
    for (int i = 0; i + 1 < n; ++i) {
      const int a = j * n + i;
      F->row(f++) << a, a + 1, a + n + 1;
      F->row(f++) << a, a + n + 1, a + n;
    }
}

}  // namespace

int main() try {
  // Lower bound 4: both terms are minimal at J = I (4 and 0). Both grow
  // without bound as det J falls to 0: the collapse-barrier tag.
  akvf::register_autodiff_energy<2>("area-aware-dirichlet",
                                    "symmetric Dirichlet + 0.5 log(det J)^2, by automatic differentiation", 4.0,
                                    AreaAwareDirichlet{}, {akvf::kCollapseBarrier});
  Eigen::MatrixXd V;
  Eigen::MatrixXi F;
  bumpy_grid(12, &V, &F);
  bool ok = true;
  for (const auto& [name, description] : akvf::preconditioners_2d().entries()) {
    akvf::ParameterizeOptions options;
    options.energy = "area-aware-dirichlet";
    options.preconditioner = name;
    options.max_iters = 3000;
    int max_flips = 0;
    options.callbacks.push_back([&](const akvf::IterationSummary& row, const Eigen::VectorXd&) {
      max_flips = std::max(max_flips, row.flips);
      return akvf::CallbackAction::kContinue;
    });
    const akvf::ParameterizeResult result = akvf::parameterize(V, F, options);
    std::cout << name << ": " << akvf::to_string(result.status) << " after " << result.iterations()
              << " iterations, energy " << result.energy() << ", grad " << result.grad_norm() << ", " << max_flips
              << " inverted at any iterate\n";
    ok &= result.status == akvf::TerminationStatus::kConverged && max_flips == 0;
  }
  return ok ? 0 : 1;
} catch (const akvf::Error& e) {
  std::cerr << "error: " << e.what() << '\n';
  return 1;
}
