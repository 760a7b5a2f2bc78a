#include "core/lie/se3.hpp"

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
using Matrix6d = Eigen::Matrix<double, 6, 6>;
using Vector6d = Eigen::Matrix<double, 6, 1>;

Vector6d tangent(const Vector3d& rho, const Vector3d& omega) {
  Vector6d xi;
  xi << rho, omega;
  return xi;
}

// Tangents covering the stress angles (with random axes) and random ones.
std::vector<Vector6d> stress_tangents(Random& rng, int random_count, bool below_pi) {
  std::vector<Vector6d> out;
  for (const double angle : stress_angles()) {
    if (below_pi && angle >= kPi) continue;
    for (int k = 0; k < 4; ++k) out.push_back(tangent(rng.vector3(5.0), rng.unit_vector() * angle));
  }
  for (int i = 0; i < random_count; ++i) out.push_back(tangent(rng.vector3(5.0), rng.rotation_vector(kPi)));
  return out;
}

TEST(SE3, ExpMatchesTheMatrixExponentialOfHat) {
  Random rng(21);
  for (const Vector6d& xi : stress_tangents(rng, 200, false))
    EXPECT_MATRIX_NEAR(SE3d::exp(xi).matrix(), test::expm_reference<4>(SE3d::hat(xi)), 1e-13)
        << "xi " << xi.transpose();
}

TEST(SE3, TangentOrderIsTranslationThenRotation) {
  // A pure [rho, 0] tangent is a pure translation by rho.
  const SE3d t = SE3d::exp(tangent(Vector3d(1, 2, 3), Vector3d::Zero()));
  EXPECT_MATRIX_NEAR(t.translation(), Vector3d(1, 2, 3), 0.0);
  EXPECT_MATRIX_NEAR(t.rotation_matrix(), Matrix3d::Identity(), 0.0);
  // A pure [0, omega] tangent is a pure rotation.
  const SE3d r = SE3d::exp(tangent(Vector3d::Zero(), Vector3d(0, 0, 0.5)));
  EXPECT_MATRIX_NEAR(r.translation(), Vector3d::Zero(), 0.0);
  EXPECT_MATRIX_NEAR(r.rotation_matrix(), SO3d::exp(Vector3d(0, 0, 0.5)).matrix(), 0.0);
}

TEST(SE3, LeftUpdateActsInTheLeftFrame) {
  // T_c_w <- exp(delta) T_c_w moves camera-frame points by the delta's translation.
  Random rng(22);
  const SE3d t_c_w = SE3d::exp(tangent(rng.vector3(2.0), rng.rotation_vector()));
  const Vector3d p_w = rng.vector3(5.0);
  const Vector3d shift(0.1, -0.2, 0.3);
  const SE3d updated = SE3d::exp(tangent(shift, Vector3d::Zero())) * t_c_w;
  EXPECT_MATRIX_NEAR(updated * p_w, t_c_w * p_w + shift, 1e-14);
}

TEST(SE3, ExpOfLogIsIdentityIncludingNearZeroAndPi) {
  Random rng(23);
  for (const Vector6d& xi : stress_tangents(rng, 1000, false)) {
    const SE3d t = SE3d::exp(xi);
    EXPECT_MATRIX_NEAR(SE3d::exp(t.log()).matrix(), t.matrix(), 1e-12) << "xi " << xi.transpose();
  }
  // Elements built from quaternions and matrices, not only from exp.
  for (int i = 0; i < 200; ++i) {
    const SE3d t(Eigen::Quaterniond(rng.quaternion_coeffs()), rng.vector3(10.0));
    EXPECT_MATRIX_NEAR(SE3d::exp(t.log()).matrix(), t.matrix(), 1e-12);
  }
}

TEST(SE3, LogOfExpRecoversTheTangentBelowPi) {
  Random rng(24);
  for (const Vector6d& xi : stress_tangents(rng, 1000, true))
    EXPECT_MATRIX_NEAR(SE3d::exp(xi).log(), xi, 1e-12) << "xi " << xi.transpose();
}

TEST(SE3, ComposeInverseAndActionAgreeWithMatrices) {
  Random rng(25);
  for (int k = 0; k < 200; ++k) {
    const SE3d a = SE3d::exp(tangent(rng.vector3(3.0), rng.rotation_vector()));
    const SE3d b = SE3d::exp(tangent(rng.vector3(3.0), rng.rotation_vector()));
    const Vector3d p = rng.vector3(10.0);
    EXPECT_MATRIX_NEAR((a * b).matrix(), a.matrix() * b.matrix(), 1e-13);
    EXPECT_MATRIX_NEAR(a.inverse().matrix(), a.matrix().inverse(), 1e-13);
    EXPECT_MATRIX_NEAR((a * a.inverse()).matrix(), Matrix4d::Identity(), 1e-14);
    EXPECT_MATRIX_NEAR(a * p, (a.matrix() * p.homogeneous()).head<3>(), 1e-13);
    EXPECT_MATRIX_NEAR((a * b) * p, a * (b * p), 1e-13);
    EXPECT_MATRIX_NEAR(a.matrix3x4(), a.matrix().topRows<3>(), 0.0);
    EXPECT_MATRIX_NEAR(a.rotation_matrix(), a.so3().matrix(), 0.0);
    EXPECT_MATRIX_NEAR(a.matrix().row(3), Eigen::RowVector4d(0, 0, 0, 1), 0.0);
    SE3d c = a;
    c *= b;
    EXPECT_MATRIX_NEAR(c.matrix(), (a * b).matrix(), 0.0);
  }
}

TEST(SE3, ConstructorsAgree) {
  Random rng(26);
  const SE3d t = SE3d::exp(tangent(rng.vector3(3.0), rng.rotation_vector()));
  EXPECT_MATRIX_NEAR(SE3d(t.matrix()).matrix(), t.matrix(), 1e-15);
  EXPECT_MATRIX_NEAR(SE3d(t.rotation_matrix(), t.translation()).matrix(), t.matrix(), 1e-15);
  EXPECT_MATRIX_NEAR(SE3d(t.unit_quaternion(), t.translation()).matrix(), t.matrix(), 1e-15);
  EXPECT_MATRIX_NEAR(SE3d().matrix(), Matrix4d::Identity(), 0.0);
}

TEST(SE3, RejectsZeroQuaternion) {
  EXPECT_THROW(SE3d(Eigen::Quaterniond(0, 0, 0, 0), Vector3d::Zero()), std::invalid_argument);
}

TEST(SE3, HatAndVee) {
  Random rng(27);
  const Vector6d xi = tangent(rng.vector3(2.0), rng.vector3(2.0));
  const Matrix4d h = SE3d::hat(xi);
  EXPECT_MATRIX_NEAR((h.topLeftCorner<3, 3>()), SO3d::hat(xi.tail<3>()), 0.0);
  EXPECT_MATRIX_NEAR((h.topRightCorner<3, 1>()), xi.head<3>(), 0.0);
  EXPECT_MATRIX_NEAR(h.row(3), Eigen::RowVector4d::Zero(), 0.0);
  EXPECT_MATRIX_NEAR(SE3d::vee(h), xi, 0.0);
}

TEST(SE3, AdjointIdentities) {
  Random rng(28);
  for (int k = 0; k < 200; ++k) {
    const SE3d a = SE3d::exp(tangent(rng.vector3(3.0), rng.rotation_vector()));
    const SE3d b = SE3d::exp(tangent(rng.vector3(3.0), rng.rotation_vector()));
    const Vector6d xi = tangent(rng.vector3(1.0), rng.rotation_vector(1.0));
    // T exp(xi) T^-1 == exp(Ad(T) xi)
    EXPECT_MATRIX_NEAR((a * SE3d::exp(xi) * a.inverse()).matrix(), SE3d::exp(a.adjoint() * xi).matrix(), 1e-12);
    // Ad(T) xi == vee(T hat(xi) T^-1)
    EXPECT_MATRIX_NEAR(a.adjoint() * xi, SE3d::vee(a.matrix() * SE3d::hat(xi) * a.inverse().matrix()), 1e-12);
    // Ad(A B) == Ad(A) Ad(B), Ad(T^-1) == Ad(T)^-1
    EXPECT_MATRIX_NEAR((a * b).adjoint(), a.adjoint() * b.adjoint(), 1e-12);
    EXPECT_MATRIX_NEAR(a.inverse().adjoint() * a.adjoint(), Matrix6d::Identity(), 1e-13);
  }
}

TEST(SE3, LeftUpdatePointJacobianMatchesCentralDifferences) {
  Random rng(29);
  for (int k = 0; k < 100; ++k) {
    const SE3d t = SE3d::exp(tangent(rng.vector3(3.0), rng.rotation_vector()));
    const Vector3d p = rng.vector3(5.0);
    Eigen::Matrix<double, 3, 6> numeric;
    const double h = 1e-6;
    for (int i = 0; i < 6; ++i) {
      const Vector6d e = Vector6d::Unit(i) * h;
      numeric.col(i) = (SE3d::exp(e) * t * p - SE3d::exp(-e) * t * p) / (2 * h);
    }
    const Eigen::Matrix<double, 3, 6> analytic = t.left_update_point_jacobian(p);
    EXPECT_MATRIX_NEAR(analytic, numeric, 1e-8);
    // The closed form [I, -hat(T p)].
    EXPECT_MATRIX_NEAR(analytic.leftCols<3>(), Matrix3d::Identity(), 0.0);
    EXPECT_MATRIX_NEAR(analytic.rightCols<3>(), -SO3d::hat(t * p), 0.0);
    EXPECT_MATRIX_NEAR(SE3d::left_update_point_jacobian_at(t * p), analytic, 0.0);
  }
}

TEST(SE3, LeftUpdatePointJacobianMatchesAutoDiff) {
  using Jet = ceres::Jet<double, 6>;
  Random rng(30);
  for (int k = 0; k < 50; ++k) {
    const SE3d t = SE3d::exp(tangent(rng.vector3(3.0), rng.rotation_vector()));
    const Vector3d p = rng.vector3(5.0);
    Eigen::Matrix<Jet, 6, 1> delta;
    for (int i = 0; i < 6; ++i) delta(i) = Jet(0.0, i);
    const Eigen::Matrix<Jet, 3, 1> moved = SE3<Jet>::exp(delta) * t.cast<Jet>() * p.cast<Jet>();
    Eigen::Matrix<double, 3, 6> auto_diff;
    for (int i = 0; i < 3; ++i) auto_diff.row(i) = moved(i).v.transpose();
    EXPECT_MATRIX_NEAR(t.left_update_point_jacobian(p), auto_diff, 1e-14);
  }
}

TEST(SE3, CastChangesTheScalar) {
  Random rng(31);
  const SE3d t = SE3d::exp(tangent(rng.vector3(3.0), rng.rotation_vector()));
  EXPECT_MATRIX_NEAR(t.cast<float>().matrix().cast<double>(), t.matrix(), 1e-5);
  const SE3<ceres::Jet<double, 2>> j = t.cast<ceres::Jet<double, 2>>();
  for (int i = 0; i < 3; ++i) EXPECT_EQ(j.translation()(i).a, t.translation()(i));
}

}  // namespace
}  // namespace facadeslam
