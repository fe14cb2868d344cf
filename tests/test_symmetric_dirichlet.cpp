// Symmetric Dirichlet (Eq. 2): derivatives by finite differences, the lower
// bound at rotations, +infinity for inverted J.
#include <doctest/doctest.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <Eigen/SVD>
#include <cmath>
#include <limits>
#include <random>

#include "energies/amips.h"
#include "energies/arap.h"
#include "energies/exp_symmetric_dirichlet.h"
#include "energies/mips.h"
#include "energies/symmetric_dirichlet.h"
#include "tests/density_checks.h"

TEST_CASE("symmetric Dirichlet derivatives match finite differences") {
  akvf::SymmetricDirichlet2D density;
  akvf::test::check_density_derivatives<2>(density, 0.5, 2.0);
}

TEST_CASE("symmetric Dirichlet derivatives near degenerate J") {
  akvf::SymmetricDirichlet2D density;
  akvf::test::check_density_derivatives<2>(density, 0.05, 20.0, 50, 11);
}

TEST_CASE("symmetric Dirichlet is 4 at every rotation and larger elsewhere") {
  akvf::SymmetricDirichlet2D density;
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
  akvf::SymmetricDirichlet2D density;
  Eigen::Matrix2d reflection;
  reflection << 1, 0, 0, -1;
  CHECK(density.value(reflection) == std::numeric_limits<double>::infinity());
  CHECK(density.value(Eigen::Matrix2d::Zero()) == std::numeric_limits<double>::infinity());
  Eigen::Matrix2d grad;
  CHECK(density.value_and_gradient(reflection, &grad) == std::numeric_limits<double>::infinity());
}

TEST_CASE("every energy's derivatives match finite differences, including near-degenerate J") {
  const akvf::Arap2D arap;
  const akvf::Mips2D mips;
  const akvf::ExpSymmetricDirichlet2D exp_sd(0.5);
  const akvf::Amips2D amips(2.0);
  for (const akvf::DistortionDensity2D* density :
       std::initializer_list<const akvf::DistortionDensity2D*>{&arap, &mips, &exp_sd, &amips}) {
    CAPTURE(density->name());
    akvf::test::check_density_derivatives<2>(*density, 0.5, 2.0);
    if (density != &exp_sd) akvf::test::check_density_derivatives<2>(*density, 0.1, 10.0, 30, 5);
  }
}

TEST_CASE("ARAP's collapse barrier: plain ARAP from g_hat up, smooth below it, unbounded at collapse") {
  const akvf::Arap2D arap;
  const double hat = akvf::Arap2D::collapse_area_ratio();
  const auto plain = [](double s1, double s2) { return (s1 - 1) * (s1 - 1) + (s2 - 1) * (s2 - 1); };
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(0.3).toRotationMatrix();
  CHECK(arap.value(R * Eigen::Vector2d(2, hat / 2).asDiagonal()) == doctest::Approx(plain(2, hat / 2)).epsilon(1e-14));
  CHECK(arap.value(R * Eigen::Vector2d(2, hat / 4).asDiagonal()) > plain(2, hat / 4));
  double previous = 0;
  for (double g : {hat / 2, 1e-6, 1e-9, 1e-12}) {
    const double value = arap.value(Eigen::Vector2d(1, g).asDiagonal());
    CHECK(value > previous);
    previous = value;
  }
  CHECK(previous > 10);
  // Singular values from 0.005 to 0.06: det J on both sides of g_hat.
  akvf::test::check_density_derivatives<2>(arap, 0.005, 0.06, 40, 3);
  akvf::test::check_filtered_hessians<2>(arap, R * Eigen::Vector2d(1.5, 2e-4).asDiagonal());
}

TEST_CASE("ARAP's collapse barrier Hessian is the clamped Hessian of the barrier term alone") {
  const akvf::Arap2D arap;
  const double hat = akvf::Arap2D::collapse_area_ratio();
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(0.4).toRotationMatrix();
  akvf::DistortionDensity2D::Hessian H;
  CHECK_FALSE(arap.collapse_barrier_hessian(R * Eigen::Vector2d(1.5, 2 * hat).asDiagonal(), &H));
  CHECK_FALSE(arap.collapse_barrier_hessian(Eigen::Vector2d(1, -hat / 2).asDiagonal(), &H));
  const Eigen::Matrix2d J =
      R * Eigen::Vector2d(1.5, hat / 3).asDiagonal() * Eigen::Rotation2Dd(-1.1).toRotationMatrix();
  akvf::test::check_collapse_barrier_hessian<2>(arap, J, 1e-6);
}

TEST_CASE("3D ARAP's collapse barrier: plain ARAP from g_hat up, smooth below it, its own closed-form eigensystem") {
  const akvf::Arap3D arap;
  const double hat = akvf::Arap3D::collapse_volume_ratio();
  const auto plain = [](const Eigen::Vector3d& sigma) { return (sigma.array() - 1).square().sum(); };
  const Eigen::Matrix3d R = Eigen::AngleAxisd(0.4, Eigen::Vector3d(1, -2, 0.5).normalized()).toRotationMatrix();
  const Eigen::Vector3d above(2, 1, hat / 1.9), below(2, 1, hat / 4);
  CHECK(arap.value(R * above.asDiagonal()) == doctest::Approx(plain(above)).epsilon(1e-14));
  CHECK(arap.value(R * below.asDiagonal()) > plain(below));
  double previous = 0;
  for (double g : {hat / 2, 1e-6, 1e-9, 1e-12}) {
    const double value = arap.value(Eigen::Vector3d(1, 1, g).asDiagonal());
    CHECK(value > previous);
    previous = value;
  }
  CHECK(previous > 10);
  akvf::DistortionDensity3D::Hessian H;
  CHECK_FALSE(arap.collapse_barrier_hessian(R * above.asDiagonal(), &H));
  // Singular values from 0.04 to 0.2: det J on both sides of g_hat.
  akvf::test::check_density_derivatives<3>(arap, 0.04, 0.2, 40, 3);
  akvf::test::check_singular_value_gradient<3>(arap, Eigen::Vector3d(1.5, 0.3, 1e-3));
  const Eigen::Matrix3d R2 = Eigen::AngleAxisd(-1.1, Eigen::Vector3d(0.3, 1, 1).normalized()).toRotationMatrix();
  bool indefinite = false;
  for (const Eigen::Vector3d& sigma :
       {Eigen::Vector3d(1.5, 0.8, 2e-4), Eigen::Vector3d(0.1, 0.1, 0.02), Eigen::Vector3d(0.05, 0.05, 0.05)}) {
    CAPTURE(sigma.transpose());
    const Eigen::Matrix3d J = R * sigma.asDiagonal() * R2;
    REQUIRE(J.determinant() < hat);
    indefinite = akvf::test::check_filtered_hessians<3>(arap, J) || indefinite;
    akvf::test::check_collapse_barrier_hessian<3>(arap, J, 1e-4 * sigma.minCoeff());
  }
  CHECK(indefinite);
}

TEST_CASE("every energy attains its lower bound at rotations and is infinite when inverted") {
  const akvf::Arap2D arap;
  const akvf::Mips2D mips;
  const akvf::ExpSymmetricDirichlet2D exp_sd(0.5);
  const akvf::Amips2D amips(2.0);
  const Eigen::Matrix2d R = Eigen::Rotation2Dd(0.7).toRotationMatrix();
  Eigen::Matrix2d reflection;
  reflection << 1, 0, 0, -1;
  for (const akvf::DistortionDensity2D* density :
       std::initializer_list<const akvf::DistortionDensity2D*>{&arap, &mips, &exp_sd, &amips}) {
    CAPTURE(density->name());
    CHECK(density->value(R) == doctest::Approx(density->lower_bound()).epsilon(1e-14));
    CHECK(density->value(R * Eigen::Vector2d(1.3, 0.9).asDiagonal()) > density->lower_bound());
    CHECK(density->value(reflection) == std::numeric_limits<double>::infinity());
  }
  CHECK(exp_sd.lower_bound() == doctest::Approx(std::exp(2.0)));
  CHECK(amips.lower_bound() == doctest::Approx(std::exp(2.0)));
}

TEST_CASE("the singular-value gradient is the derivative of D along the singular values") {
  const akvf::Arap2D arap;
  const akvf::SymmetricDirichlet2D sd;
  for (const akvf::DistortionDensity2D* density : std::initializer_list<const akvf::DistortionDensity2D*>{&arap, &sd})
    akvf::test::check_singular_value_gradient<2>(*density, Eigen::Vector2d(1.7, 0.6));
}

TEST_CASE("every 3D energy: derivatives by finite differences, bounds, inversion") {
  const akvf::SymmetricDirichlet3D sd;
  const akvf::ExpSymmetricDirichlet3D exp_sd(0.2);
  const akvf::Mips3D mips;
  const akvf::Amips3D amips(0.5);
  const akvf::Arap3D arap;
  for (const akvf::DistortionDensity<3>* density :
       std::initializer_list<const akvf::DistortionDensity<3>*>{&sd, &exp_sd, &mips, &amips, &arap}) {
    CAPTURE(density->name());
    akvf::test::check_density_derivatives<3>(*density, 0.5, 2.0, 30);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(0.7, Eigen::Vector3d(1, 2, 3).normalized()).toRotationMatrix();
    CHECK(density->value(R) == doctest::Approx(density->lower_bound()).epsilon(1e-14));
    CHECK(density->value(R * Eigen::Vector3d(1.2, 1, 0.9).asDiagonal()) > density->lower_bound());
    CHECK(density->value(-R) == std::numeric_limits<double>::infinity());
  }
  akvf::test::check_density_derivatives<3>(sd, 0.1, 10.0, 20, 9);
  CHECK(sd.lower_bound() == 6.0);
  // MIPS is scale invariant: 3 at every similarity, not only at rotations.
  CHECK(mips.value(2.5 * Eigen::Matrix3d::Identity()) == doctest::Approx(3.0).epsilon(1e-14));
}

TEST_CASE("3D singular-value derivatives match finite differences in sigma") {
  const akvf::SymmetricDirichlet3D sd;
  const akvf::Amips3D amips(0.5);
  const akvf::Arap3D arap;
  for (const akvf::DistortionDensity<3>* density :
       std::initializer_list<const akvf::DistortionDensity<3>*>{&sd, &amips, &arap}) {
    CAPTURE(density->name());
    akvf::test::check_singular_value_gradient<3>(*density, Eigen::Vector3d(1.7, 0.8, 0.45));
  }
}

TEST_CASE("every 2D energy's closed-form eigensystem and filtered Hessians agree with its Hessian") {
  const akvf::SymmetricDirichlet2D sd;
  const akvf::Arap2D arap;
  const akvf::Mips2D mips;
  const akvf::ExpSymmetricDirichlet2D exp_sd(0.5);
  const akvf::Amips2D amips(2.0);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-3.14, 3.14), stretch(0.2, 3.0);
  int indefinite = 0;
  for (const akvf::DistortionDensity2D* density :
       std::initializer_list<const akvf::DistortionDensity2D*>{&sd, &arap, &mips, &exp_sd, &amips}) {
    CAPTURE(density->name());
    for (int trial = 0; trial < 200; ++trial) {
      // J = R(a) diag(s1, s2) R(b), with equal singular values now and then.
      const double s1 = stretch(rng), s2 = trial % 10 == 0 ? s1 : stretch(rng);
      const Eigen::Matrix2d J = Eigen::Rotation2Dd(angle(rng)).toRotationMatrix() *
                                Eigen::Vector2d(s1, s2).asDiagonal() *
                                Eigen::Rotation2Dd(angle(rng)).toRotationMatrix();
      if (density == &exp_sd && J.squaredNorm() > 8) continue;  // exp(k (s + s/g^2)) overflows the tolerance
      indefinite += akvf::test::check_filtered_hessians<2>(*density, J);
      const auto* eigensystem = dynamic_cast<const akvf::HessianEigensystem<2>*>(density);
      REQUIRE(eigensystem);
      akvf::test::check_eigensystem<2>(*eigensystem, *density, J);
    }
  }
  CHECK(indefinite > 100);  // the clamping and the mirroring were exercised
}

TEST_CASE("every 3D energy's closed-form eigensystem and filtered Hessians agree with its Hessian") {
  const akvf::SymmetricDirichlet3D sd;
  const akvf::Arap3D arap;
  const akvf::Mips3D mips;
  const akvf::ExpSymmetricDirichlet3D exp_sd(0.5);
  const akvf::Amips3D amips(2.0);
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> angle(-3.14, 3.14), coordinate(-1, 1), stretch(0.3, 2.5);
  const auto rotation = [&] {
    const Eigen::Vector3d axis(coordinate(rng), coordinate(rng), coordinate(rng));
    return Eigen::AngleAxisd(angle(rng), axis.normalized()).toRotationMatrix();
  };
  int indefinite = 0;
  for (const akvf::DistortionDensity3D* density :
       std::initializer_list<const akvf::DistortionDensity3D*>{&sd, &arap, &mips, &exp_sd, &amips}) {
    CAPTURE(density->name());
    for (int trial = 0; trial < 200; ++trial) {
      // J = R diag(sigma) R', with two or three equal singular values now and then.
      Eigen::Vector3d sigma(stretch(rng), stretch(rng), stretch(rng));
      if (trial % 10 == 0) sigma[1] = sigma[0];
      if (trial % 20 == 0) sigma[2] = sigma[0];
      const Eigen::Matrix3d J = rotation() * sigma.asDiagonal() * rotation();
      CAPTURE(sigma.transpose());
      if (density == &exp_sd && J.squaredNorm() > 6) continue;  // exp(k (s + c/g^2)) overflows the tolerance
      indefinite += akvf::test::check_filtered_hessians<3>(*density, J);
      const auto* eigensystem = dynamic_cast<const akvf::HessianEigensystem<3>*>(density);
      REQUIRE(eigensystem);
      akvf::test::check_eigensystem<3>(*eigensystem, *density, J);
    }
  }
  CHECK(indefinite > 100);  // the clamping and the mirroring were exercised
}
