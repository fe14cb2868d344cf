// Symmetric Dirichlet (Eq. 2): derivatives by finite differences, the lower
// bound at rotations, +infinity for inverted J.
#include <doctest/doctest.h>

#include <Eigen/Geometry>
#include <limits>

#include "energies/symmetric_dirichlet.h"
#include "tests/density_checks.h"

TEST_CASE("symmetric Dirichlet derivatives match finite differences") {
  akvf::SymmetricDirichlet2 density;
  akvf::test::check_density_derivatives<2>(density, 0.5, 2.0);
}

TEST_CASE("symmetric Dirichlet derivatives near degenerate J") {
  akvf::SymmetricDirichlet2 density;
  akvf::test::check_density_derivatives<2>(density, 0.05, 20.0, 50, 11);
}

TEST_CASE("symmetric Dirichlet is 4 at every rotation and larger elsewhere") {
  akvf::SymmetricDirichlet2 density;
  for (double angle : {0.0, 0.3, 2.0, -1.0}) {
    const Eigen::Matrix2d R = Eigen::Rotation2Dd(angle).toRotationMatrix();
    CHECK(density.value(R) == doctest::Approx(4.0).epsilon(1e-15));
    Eigen::Matrix2d grad;
    density.value_and_gradient(R, &grad);
    CHECK(grad.norm() <= 1e-14);
    CHECK(density.value(1.1 * R) > 4.0);
  }
}

TEST_CASE("symmetric Dirichlet is infinite for inverted or degenerate J") {
  akvf::SymmetricDirichlet2 density;
  Eigen::Matrix2d reflection;
  reflection << 1, 0, 0, -1;
  CHECK(density.value(reflection) == std::numeric_limits<double>::infinity());
  CHECK(density.value(Eigen::Matrix2d::Zero()) == std::numeric_limits<double>::infinity());
  Eigen::Matrix2d grad;
  CHECK(density.value_and_gradient(reflection, &grad) == std::numeric_limits<double>::infinity());
}
