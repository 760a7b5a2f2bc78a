#include "core/lie/sim3.hpp"

#include <cmath>
#include <stdexcept>

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "tests/core/lie/lie_test_utils.hpp"

namespace facadeslam {
namespace {

using Eigen::Matrix3d;
using Eigen::Matrix4d;
using Eigen::Vector3d;
using test::kPi;
using test::Random;
using test::stress_angles;
using Matrix7d = Eigen::Matrix<double, 7, 7>;
using Vector7d = Eigen::Matrix<double, 7, 1>;

Vector7d tangent(const Vector3d& rho, const Vector3d& omega, double sigma) {
  Vector7d xi;
  xi << rho, omega, sigma;
  return xi;
}

// Log-scales near 0, around the moment series switch (|sigma| = 1), and large.
std::vector<double> stress_sigmas() {
  return {0.0,    1e-12, -1e-12, 1e-8,  -1e-8,  1e-4, -1e-4, 0.3, -0.3, 0.999,
          -0.999, 1.0,   -1.0,   1.001, -1.001, 2.5,  -2.5,  6.0, -6.0};
}

std::vector<Vector7d> stress_tangents(Random& rng, bool below_pi) {
  std::vector<Vector7d> out;
  for (const double angle : stress_angles()) {
    if (below_pi && angle >= kPi) continue;
    for (const double sigma : stress_sigmas())
      out.push_back(tangent(rng.vector3(3.0), rng.unit_vector() * angle, sigma));
  }
  for (int i = 0; i < 500; ++i)
    out.push_back(tangent(rng.vector3(3.0), rng.rotation_vector(kPi), rng.uniform(-3.0, 3.0)));
  return out;
}

Sim3d random_sim3(Random& rng) {
  return Sim3d::exp(tangent(rng.vector3(3.0), rng.rotation_vector(), rng.uniform(-2.0, 2.0)));
}

TEST(Sim3, ExpMatchesTheMatrixExponentialOfHat) {
  // Covers every branch of the W coefficients: theta small or not, sigma in
  // the series range, at its edge, and beyond.
  Random rng(41);
  for (const Vector7d& xi : stress_tangents(rng, false)) {
    const Matrix4d expected = test::expm_reference<4>(Sim3d::hat(xi));
    const double scale = std::max(1.0, expected.cwiseAbs().maxCoeff());
    EXPECT_LE(test::max_abs_diff(Sim3d::exp(xi).matrix(), expected), 1e-13 * scale) << "xi " << xi.transpose();
  }
}

TEST(Sim3, ZeroSigmaIsSE3) {
  Random rng(42);
  for (const double angle : stress_angles()) {
    const Vector3d rho = rng.vector3(3.0);
    const Vector3d omega = rng.unit_vector() * angle;
    Eigen::Matrix<double, 6, 1> xi6;
    xi6 << rho, omega;
    EXPECT_MATRIX_NEAR(Sim3d::exp(tangent(rho, omega, 0.0)).matrix(), SE3d::exp(xi6).matrix(), 1e-14);
    EXPECT_MATRIX_NEAR(Sim3d::w_matrix(omega, 0.0), SO3d::left_jacobian(omega), 1e-15);
  }
}

TEST(Sim3, WCoefficientsAreContinuousAcrossTheirBranches) {
  // Both sides of theta^2 = 1 and of |sigma| = 1 agree (a wrong series
  // coefficient or closed form would show up as a jump).
  Random rng(43);
  const double theta_switch = std::sqrt(lie_detail::kSeriesAngleSq);
  for (const double sigma : stress_sigmas()) {
    const Vector3d axis = rng.unit_vector();
    const Matrix3d below = Sim3d::w_matrix(axis * theta_switch * (1 - 1e-15), sigma);
    const Matrix3d above = Sim3d::w_matrix(axis * theta_switch * (1 + 1e-15), sigma);
    EXPECT_MATRIX_NEAR(below, above, 1e-14 * std::max(1.0, below.norm())) << "sigma " << sigma;
  }
  for (const double angle : stress_angles()) {
    const Vector3d omega = rng.unit_vector() * angle;
    for (const double edge : {-1.0, 1.0}) {
      const Matrix3d below = Sim3d::w_matrix(omega, edge * (1 - 1e-15));
      const Matrix3d above = Sim3d::w_matrix(omega, edge * (1 + 1e-15));
      EXPECT_MATRIX_NEAR(below, above, 1e-14) << "angle " << angle;
    }
  }
}

TEST(Sim3, ExpOfLogIsIdentity) {
  Random rng(44);
  for (const Vector7d& xi : stress_tangents(rng, false)) {
    const Sim3d s = Sim3d::exp(xi);
    const double scale = std::max(1.0, s.matrix().cwiseAbs().maxCoeff());
    EXPECT_LE(test::max_abs_diff(Sim3d::exp(s.log()).matrix(), s.matrix()), 1e-12 * scale) << "xi " << xi.transpose();
  }
}

TEST(Sim3, LogOfExpRecoversTheTangentBelowPi) {
  Random rng(45);
  for (const Vector7d& xi : stress_tangents(rng, true))
    EXPECT_MATRIX_NEAR(Sim3d::exp(xi).log(), xi, 1e-12) << "xi " << xi.transpose();
}

TEST(Sim3, ComposeInverseAndActionAgreeWithMatrices) {
  Random rng(46);
  for (int k = 0; k < 200; ++k) {
    const Sim3d a = random_sim3(rng);
    const Sim3d b = random_sim3(rng);
    const Vector3d p = rng.vector3(10.0);
    const double tol = 1e-13 * std::max({1.0, a.scale(), b.scale(), 1.0 / a.scale()});
    EXPECT_MATRIX_NEAR((a * b).matrix(), a.matrix() * b.matrix(), 10 * tol);
    EXPECT_MATRIX_NEAR(a.inverse().matrix(), a.matrix().inverse(), 10 * tol);
    EXPECT_MATRIX_NEAR((a * a.inverse()).matrix(), Matrix4d::Identity(), tol);
    EXPECT_MATRIX_NEAR(a * p, a.scale() * (a.rotation_matrix() * p) + a.translation(), 10 * tol);
    EXPECT_MATRIX_NEAR(a * p, (a.matrix() * p.homogeneous()).head<3>(), 10 * tol);
    EXPECT_MATRIX_NEAR((a * b) * p, a * (b * p), 100 * tol);
    EXPECT_MATRIX_NEAR(a.matrix3x4(), a.matrix().topRows<3>(), 0.0);
    EXPECT_NEAR((a * b).scale(), a.scale() * b.scale(), 1e-15 * (a * b).scale());
  }
}

TEST(Sim3, MatrixConstructorRecoversScaleRotationAndTranslation) {
  Random rng(47);
  for (int k = 0; k < 50; ++k) {
    const Sim3d s = random_sim3(rng);
    const Sim3d back(s.matrix());
    EXPECT_NEAR(back.scale(), s.scale(), 1e-14 * s.scale());
    EXPECT_MATRIX_NEAR(back.rotation_matrix(), s.rotation_matrix(), 1e-14);
    EXPECT_MATRIX_NEAR(back.translation(), s.translation(), 0.0);
  }
  EXPECT_MATRIX_NEAR(Sim3d().matrix(), Matrix4d::Identity(), 0.0);
}

TEST(Sim3, SE3ConstructorAndRigidPart) {
  Random rng(48);
  Eigen::Matrix<double, 6, 1> xi6;
  xi6 << rng.vector3(2.0), rng.rotation_vector();
  const SE3d pose = SE3d::exp(xi6);
  const Sim3d s(pose, 2.0);
  EXPECT_MATRIX_NEAR(s.se3().matrix(), pose.matrix(), 0.0);
  EXPECT_EQ(s.scale(), 2.0);
}

TEST(Sim3, RejectsNonPositiveOrNonFiniteScale) {
  for (const double bad : {0.0, -1.0, double(NAN), double(INFINITY)})
    EXPECT_THROW(Sim3d(SO3d(), Vector3d::Zero(), bad), std::invalid_argument) << bad;
}

TEST(Sim3, MatrixConstructorRejectsNonPositiveDeterminant) {
  Matrix4d m = Matrix4d::Identity();
  m(2, 2) = -1.0;  // a reflection
  EXPECT_THROW(Sim3d{m}, std::invalid_argument);
  EXPECT_THROW(Sim3d{Matrix4d::Zero().eval()}, std::invalid_argument);
}

TEST(Sim3, HatAndVee) {
  Random rng(49);
  const Vector7d xi = tangent(rng.vector3(2.0), rng.vector3(2.0), 0.7);
  const Matrix4d h = Sim3d::hat(xi);
  EXPECT_MATRIX_NEAR((h.topLeftCorner<3, 3>()), SO3d::hat(xi.segment<3>(3)) + 0.7 * Matrix3d::Identity(), 0.0);
  EXPECT_MATRIX_NEAR((h.topRightCorner<3, 1>()), xi.head<3>(), 0.0);
  EXPECT_MATRIX_NEAR(Sim3d::vee(h), xi, 1e-15);
}

TEST(Sim3, AdjointIdentities) {
  Random rng(50);
  for (int k = 0; k < 200; ++k) {
    const Sim3d a = random_sim3(rng);
    const Sim3d b = random_sim3(rng);
    const Vector7d xi = tangent(rng.vector3(1.0), rng.rotation_vector(1.0), rng.uniform(-0.5, 0.5));
    const Sim3d lhs = a * Sim3d::exp(xi) * a.inverse();
    const Sim3d rhs = Sim3d::exp(a.adjoint() * xi);
    const double tol = 1e-12 * std::max(1.0, lhs.matrix().cwiseAbs().maxCoeff());
    EXPECT_MATRIX_NEAR(lhs.matrix(), rhs.matrix(), tol);
    EXPECT_MATRIX_NEAR(a.adjoint() * xi, Sim3d::vee(a.matrix() * Sim3d::hat(xi) * a.inverse().matrix()), 1e-11);
    const Matrix7d ad_ab = (a * b).adjoint();
    EXPECT_MATRIX_NEAR(ad_ab, a.adjoint() * b.adjoint(), 1e-12 * std::max(1.0, ad_ab.norm()));
    EXPECT_MATRIX_NEAR(a.inverse().adjoint() * a.adjoint(), Matrix7d::Identity(), 1e-12);
  }
}

TEST(Sim3, LeftUpdatePointJacobianMatchesCentralDifferences) {
  Random rng(51);
  for (int k = 0; k < 100; ++k) {
    const Sim3d s = random_sim3(rng);
    const Vector3d p = rng.vector3(5.0);
    Eigen::Matrix<double, 3, 7> numeric;
    const double h = 1e-6;
    for (int i = 0; i < 7; ++i) {
      const Vector7d e = Vector7d::Unit(i) * h;
      numeric.col(i) = (Sim3d::exp(e) * s * p - Sim3d::exp(-e) * s * p) / (2 * h);
    }
    const double scale = std::max(1.0, (s * p).norm());
    EXPECT_MATRIX_NEAR(s.left_update_point_jacobian(p), numeric, 1e-8 * scale);
  }
}

TEST(Sim3, ExpIsDifferentiableWithJetsAtTheIdentity) {
  // d exp(delta) p / d delta at 0 = [I, -hat(p), p]: exercises every series
  // branch with Jet scalars (where sqrt(0) would have no derivative).
  using Jet = ceres::Jet<double, 7>;
  const Vector3d p(0.3, -1.2, 2.0);
  Eigen::Matrix<Jet, 7, 1> delta;
  for (int i = 0; i < 7; ++i) delta(i) = Jet(0.0, i);
  const Eigen::Matrix<Jet, 3, 1> moved = Sim3<Jet>::exp(delta) * p.cast<Jet>();
  Eigen::Matrix<double, 3, 7> auto_diff;
  for (int i = 0; i < 3; ++i) auto_diff.row(i) = moved(i).v.transpose();
  EXPECT_MATRIX_NEAR(auto_diff, Sim3d().left_update_point_jacobian(p), 1e-15);
}

TEST(Sim3, CastChangesTheScalar) {
  Random rng(52);
  const Sim3d s = random_sim3(rng);
  const Sim3f f = s.cast<float>();
  EXPECT_NEAR(f.scale(), s.scale(), 1e-6 * s.scale());
  const Sim3<ceres::Jet<double, 2>> j = s.cast<ceres::Jet<double, 2>>();
  EXPECT_EQ(j.scale().a, s.scale());
}

}  // namespace
}  // namespace facadeslam
