// Every built-in energy against the same density written once as a template
// and differentiated automatically (akvf/autodiff_density.h): values,
// gradients and Hessians agree; the automatic densities pass the finite-
// difference checker; a registered user energy appears in the registry and
// is refused a second time.
#include <doctest/doctest.h>

#include <cmath>
#include <random>

#include "akvf/catalog.h"
#include "akvf/extend.h"
#include "preconditioners/energy_scale.h"
#include "tests/density_checks.h"
#include "tests/test_support.h"

namespace {

using std::exp;
using std::log;
using std::pow;
using std::sqrt;

// The densities of docs/energies.md as functions of J, k the exponent.
struct SymmetricDirichlet {
  template <class T, int D>
  T operator()(const Eigen::Matrix<T, D, D>& J) const {
    return J.squaredNorm() + J.inverse().squaredNorm();
  }
};
struct Arap2 {  // |J - R|^2 = |J|^2 - 2 (sigma_1 + sigma_2) + 2, sigma_1 + sigma_2 = sqrt(|J|^2 + 2 det J)
  template <class T>
  T operator()(const Eigen::Matrix<T, 2, 2>& J) const {
    return J.squaredNorm() - T(2.0) * sqrt(J.squaredNorm() + T(2.0) * J.determinant()) + T(2.0);
  }
};
struct Mips {  // |J|^2 / det^(2/D)
  template <class T, int D>
  T operator()(const Eigen::Matrix<T, D, D>& J) const {
    return J.squaredNorm() / pow(J.determinant(), 2.0 / D);
  }
};
struct ExpSymmetricDirichlet {
  double k;
  template <class T, int D>
  T operator()(const Eigen::Matrix<T, D, D>& J) const {
    return exp(T(k) * (J.squaredNorm() + J.inverse().squaredNorm()));
  }
};
struct Amips {  // exp(k (|J|^2 / (2 D det^(2/D)) + (det + 1/det) / 4))
  double k;
  template <class T, int D>
  T operator()(const Eigen::Matrix<T, D, D>& J) const {
    const T det = J.determinant();
    return exp(T(k) * (J.squaredNorm() / (T(2.0 * D) * pow(det, 2.0 / D)) + (det + T(1.0) / det) / T(4.0)));
  }
};

template <int Dim>
std::unique_ptr<akvf::DistortionDensity<Dim>> built_in_energy(const std::string& name,
                                                              const akvf::EnergySettings& settings) {
  if constexpr (Dim == 2)
    return akvf::energies_2d().create(name, settings);
  else
    return akvf::energies_3d().create(name, settings);
}

// Built-in and automatic densities agree at random J (det > 0).
template <int Dim, class Functor>
void check_against(const std::string& name, Functor functor, double exponent) {
  CAPTURE(name);
  CAPTURE(Dim);
  akvf::EnergySettings settings;
  settings.exponent = exponent;
  const auto built_in = built_in_energy<Dim>(name, settings);
  const akvf::AutodiffDensity<Dim, Functor> automatic(name, built_in->lower_bound(), functor);
  std::mt19937 rng(11);
  for (int sample = 0; sample < 30; ++sample) {
    const auto J = akvf::test::random_jacobian<Dim>(rng, 0.5, 2.0);
    Eigen::Matrix<double, Dim, Dim> g1, g2;
    const double v1 = built_in->value_and_gradient(J, &g1), v2 = automatic.value_and_gradient(J, &g2);
    CHECK(v2 == doctest::Approx(v1).epsilon(1e-12));
    CHECK((g1 - g2).norm() <= 1e-10 * (1 + g1.norm()));
    const auto H1 = built_in->hessian(J), H2 = automatic.hessian(J);
    CHECK((H1 - H2).norm() <= 1e-9 * (1 + H1.norm()));
  }
  akvf::test::check_density_derivatives<Dim>(automatic, 0.5, 2.0, 10);
}

}  // namespace

TEST_CASE("every built-in 2D energy agrees with its density differentiated automatically") {
  check_against<2>("symmetric-dirichlet", SymmetricDirichlet{}, 1);
  check_against<2>("arap", Arap2{}, 1);
  check_against<2>("mips", Mips{}, 1);
  check_against<2>("exp-symmetric-dirichlet", ExpSymmetricDirichlet{0.1}, 0.1);
  check_against<2>("amips", Amips{0.5}, 0.5);
}

TEST_CASE("every built-in 3D energy but ARAP agrees with its density differentiated automatically") {
  // 3D ARAP needs the rotation of the polar decomposition (an SVD), which
  // has no closed form to differentiate here; its derivatives are checked by
  // finite differences in test_tet_objective.cpp.
  check_against<3>("symmetric-dirichlet", SymmetricDirichlet{}, 1);
  check_against<3>("mips", Mips{}, 1);
  check_against<3>("exp-symmetric-dirichlet", ExpSymmetricDirichlet{0.1}, 0.1);
  check_against<3>("amips", Amips{0.5}, 0.5);
}

TEST_CASE("the singular-value derivative of an automatic density is that of the built-in one (SLIM's input)") {
  const auto built_in = akvf::energies_2d().create("symmetric-dirichlet", {});
  const auto& sv = dynamic_cast<const akvf::SingularValueDerivative<2>&>(*built_in);
  const akvf::AutodiffDensity<2, SymmetricDirichlet> automatic("sd", 4, SymmetricDirichlet{});
  const Eigen::Vector2d sigma(1.7, 0.4);
  CHECK((automatic.singular_value_gradient(sigma) - sv.singular_value_gradient(sigma)).norm() < 1e-12);
  CHECK(automatic.value(Eigen::Matrix2d::Identity()) == 4);
  Eigen::Matrix2d flipped = Eigen::Matrix2d::Identity();
  flipped(0, 0) = -1;
  CHECK(std::isinf(automatic.value(flipped)));
}

TEST_CASE("a registered energy is listed by name, and its name cannot be taken twice") {
  akvf::register_autodiff_energy<2>("test-registered-sd", "symmetric Dirichlet by automatic differentiation", 4.0,
                                    SymmetricDirichlet{});
  bool listed = false;
  for (const auto& [name, description] : akvf::energies_2d().entries()) listed |= name == "test-registered-sd";
  CHECK(listed);
  CHECK(akvf::test::error_message([] {
          akvf::register_autodiff_energy<2>("test-registered-sd", "again", 4.0, SymmetricDirichlet{});
        }) == "energy 'test-registered-sd' is already registered");
  CHECK(akvf::energies_2d().create("test-registered-sd", {})->lower_bound() == 4.0);
}

// docs/extending.md's example: a log(det J)^2 term stiffens dilations only,
// by 4 against symmetric Dirichlet's 16 along both (energy_scale.h).
namespace {
struct AreaAwareDirichlet {
  template <class T>
  T operator()(const Eigen::Matrix<T, 2, 2>& J) const {
    return J.squaredNorm() + J.inverse().squaredNorm() + T(0.5) * log(J.determinant()) * log(J.determinant());
  }
};
}  // namespace

TEST_CASE("AKVF's divergence weight follows a registered energy's Hessian at the identity") {
  const akvf::AutodiffDensity<2, AreaAwareDirichlet> area_aware("area-aware", 4.0, AreaAwareDirichlet{});
  CHECK(akvf::rest_divergence_weight(area_aware) == doctest::Approx(1.25).epsilon(1e-12));
  const akvf::AutodiffDensity<2, Mips> mips("mips", 2.0, Mips{});
  CHECK(akvf::rest_divergence_weight(mips) == 0.0);
}
