#include "core/lie/so3.hpp"

#include <cmath>
#include <stdexcept>

#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "tests/core/lie/lie_test_utils.hpp"

namespace facadeslam {
namespace {

using Eigen::Matrix3d;
using Eigen::Vector3d;
using test::kPi;
using test::Random;
using test::stress_angles;

// Rotation matrices from axis-angle, computed by Eigen (independent of SO3).
Matrix3d angle_axis_matrix(const Vector3d& omega) {
  const double theta = omega.norm();
  if (theta == 0.0) return Matrix3d::Identity();
  return Eigen::AngleAxisd(theta, omega / theta).toRotationMatrix();
}

std::vector<SO3d> stress_rotations(Random& rng, int random_count) {
  std::vector<SO3d> out;
  for (const double angle : stress_angles())
    for (int k = 0; k < 4; ++k) out.push_back(SO3d::exp(rng.unit_vector() * angle));
  for (int i = 0; i < random_count; ++i) out.push_back(SO3d(Eigen::Quaterniond(rng.quaternion_coeffs())));
  return out;
}

TEST(SO3, ExpMatchesAngleAxisRotation) {
  Random rng(1);
  for (const double angle : stress_angles()) {
    for (int k = 0; k < 5; ++k) {
      const Vector3d omega = rng.unit_vector() * angle;
      EXPECT_MATRIX_NEAR(SO3d::exp(omega).matrix(), angle_axis_matrix(omega), 1e-15);
    }
  }
  // Beyond pi the exponential still is the rotation by |omega| about the axis.
  const Vector3d big = rng.unit_vector() * 5.0;
  EXPECT_MATRIX_NEAR(SO3d::exp(big).matrix(), angle_axis_matrix(big), 1e-14);
}

TEST(SO3, ExpRotatesCounterClockwiseAboutTheAxis) {
  // A quarter turn about +z maps +x to +y (right-handed convention).
  const SO3d r = SO3d::exp(Vector3d(0, 0, kPi / 2));
  EXPECT_MATRIX_NEAR(r * Vector3d(1, 0, 0), Vector3d(0, 1, 0), 1e-15);
}

TEST(SO3, ExpOfLogIsIdentityIncludingNearZeroAndPi) {
  Random rng(2);
  for (const SO3d& r : stress_rotations(rng, 1000)) {
    const Vector3d omega = r.log();
    EXPECT_LE(omega.norm(), kPi + 1e-15);
    EXPECT_MATRIX_NEAR(SO3d::exp(omega).matrix(), r.matrix(), 1e-12);
  }
}

TEST(SO3, LogOfExpRecoversTheTangentBelowPi) {
  Random rng(3);
  std::vector<Vector3d> omegas;
  for (const double angle : stress_angles())
    if (angle < kPi)
      for (int k = 0; k < 4; ++k) omegas.push_back(rng.unit_vector() * angle);
  for (int i = 0; i < 1000; ++i) omegas.push_back(rng.rotation_vector(kPi));
  for (const Vector3d& omega : omegas)
    EXPECT_MATRIX_NEAR(SO3d::exp(omega).log(), omega, 1e-12) << "angle " << omega.norm();
}

TEST(SO3, LogNearPiFromAMatrixIsAccurate) {
  // The matrix path (SVD projection, matrix -> quaternion) must keep the tiny
  // skew part that decides the sign of the axis near pi.
  Random rng(4);
  for (const double gap : {1e-3, 1e-6, 1e-9}) {
    for (int k = 0; k < 10; ++k) {
      const Vector3d omega = rng.unit_vector() * (kPi - gap);
      const SO3d r(angle_axis_matrix(omega));
      EXPECT_MATRIX_NEAR(r.log(), omega, 1e-12) << "gap " << gap;
    }
  }
}

TEST(SO3, LogAtExactlyPiHasAnglePiAndRoundTrips) {
  Random rng(5);
  for (int k = 0; k < 20; ++k) {
    const Vector3d axis = rng.unit_vector();
    // R = 2 a a^T - I is exactly the half turn about a.
    const Matrix3d half_turn = 2.0 * axis * axis.transpose() - Matrix3d::Identity();
    const SO3d r(half_turn);
    const Vector3d omega = r.log();
    EXPECT_NEAR(omega.norm(), kPi, 1e-14);
    EXPECT_NEAR(std::abs(omega.normalized().dot(axis)), 1.0, 1e-14);
    EXPECT_MATRIX_NEAR(SO3d::exp(omega).matrix(), half_turn, 1e-14);
  }
}

TEST(SO3, LogIgnoresTheQuaternionSign) {
  Random rng(6);
  for (int k = 0; k < 100; ++k) {
    const Eigen::Vector4d q = rng.quaternion_coeffs();
    const SO3d a{Eigen::Quaterniond(q)};
    const SO3d b{Eigen::Quaterniond(Eigen::Vector4d(-q))};
    EXPECT_MATRIX_NEAR(a.log(), b.log(), 1e-15);
  }
}

TEST(SO3, ComposeInverseAndActionAgreeWithMatrices) {
  Random rng(7);
  for (int k = 0; k < 200; ++k) {
    const SO3d a = SO3d::exp(rng.rotation_vector());
    const SO3d b = SO3d::exp(rng.rotation_vector());
    const Vector3d p = rng.vector3(10.0);
    EXPECT_MATRIX_NEAR((a * b).matrix(), a.matrix() * b.matrix(), 1e-14);
    EXPECT_MATRIX_NEAR(a.inverse().matrix(), a.matrix().transpose(), 1e-15);
    EXPECT_MATRIX_NEAR((a * a.inverse()).matrix(), Matrix3d::Identity(), 1e-15);
    EXPECT_MATRIX_NEAR(a * p, a.matrix() * p, 1e-13);
    EXPECT_MATRIX_NEAR((a * b) * p, a * (b * p), 1e-13);
    SO3d c = a;
    c *= b;
    EXPECT_MATRIX_NEAR(c.matrix(), (a * b).matrix(), 0.0);
  }
}

TEST(SO3, LongProductsStayUnit) {
  Random rng(8);
  SO3d r;
  for (int k = 0; k < 100000; ++k) r *= SO3d::exp(rng.rotation_vector(0.1));
  EXPECT_NEAR(r.unit_quaternion().norm(), 1.0, 1e-15);
  EXPECT_MATRIX_NEAR(r.matrix() * r.matrix().transpose(), Matrix3d::Identity(), 1e-14);
}

TEST(SO3, HatAndVee) {
  Random rng(9);
  for (int k = 0; k < 50; ++k) {
    const Vector3d a = rng.vector3(3.0);
    const Vector3d b = rng.vector3(3.0);
    EXPECT_MATRIX_NEAR(SO3d::hat(a) * b, a.cross(b), 1e-14);
    EXPECT_MATRIX_NEAR(SO3d::hat(a) + SO3d::hat(a).transpose(), Matrix3d::Zero(), 0.0);
    EXPECT_MATRIX_NEAR(SO3d::vee(SO3d::hat(a)), a, 0.0);
  }
}

TEST(SO3, AdjointIsTheRotationMatrix) {
  Random rng(10);
  for (int k = 0; k < 100; ++k) {
    const SO3d r = SO3d::exp(rng.rotation_vector());
    const Vector3d omega = rng.rotation_vector(1.0);
    EXPECT_MATRIX_NEAR((r * SO3d::exp(omega) * r.inverse()).matrix(), SO3d::exp(r.adjoint() * omega).matrix(), 1e-14);
    EXPECT_MATRIX_NEAR(r.adjoint(), r.matrix(), 0.0);
  }
}

TEST(SO3, QuaternionConstructorNormalises) {
  const SO3d r{Eigen::Quaterniond(2.0, 0.0, 0.0, 0.0)};
  EXPECT_NEAR(r.unit_quaternion().norm(), 1.0, 1e-16);
  EXPECT_MATRIX_NEAR(r.matrix(), Matrix3d::Identity(), 1e-16);
  const Eigen::Quaterniond q(0.3, -0.2, 0.9, 0.4);
  const SO3d s(q);
  EXPECT_MATRIX_NEAR(s.matrix(), q.normalized().toRotationMatrix(), 1e-15);
  // data() exposes the coefficients in Eigen's [x, y, z, w] order.
  const Eigen::Quaterniond qn = q.normalized();
  EXPECT_DOUBLE_EQ(s.data()[0], qn.x());
  EXPECT_DOUBLE_EQ(s.data()[3], qn.w());
}

TEST(SO3, MatrixConstructorProjectsOntoTheNearestRotation) {
  Random rng(11);
  for (int k = 0; k < 50; ++k) {
    const Matrix3d r = angle_axis_matrix(rng.rotation_vector());
    // A uniformly scaled rotation: the nearest rotation is r itself.
    EXPECT_MATRIX_NEAR(SO3d(Matrix3d(2.5 * r)).matrix(), r, 1e-14);
    // A slightly perturbed one: the result is a proper rotation close to r.
    Matrix3d noisy = r;
    for (int i = 0; i < 9; ++i) noisy(i / 3, i % 3) += rng.uniform(-1e-6, 1e-6);
    const Matrix3d fixed = SO3d(noisy).matrix();
    EXPECT_MATRIX_NEAR(fixed * fixed.transpose(), Matrix3d::Identity(), 4e-15);
    EXPECT_NEAR(fixed.determinant(), 1.0, 4e-15);
    EXPECT_MATRIX_NEAR(fixed, r, 5e-6);
    // Projection never moves further than the input's distance to r.
    EXPECT_LE((fixed - noisy).norm(), (r - noisy).norm() + 1e-15);
  }
}

TEST(SO3, MatrixConstructorTurnsAReflectionIntoAProperRotation) {
  const Matrix3d reflection = Eigen::Vector3d(1.0, 1.0, -1.0).asDiagonal();
  const Matrix3d r = SO3d(reflection).matrix();
  EXPECT_NEAR(r.determinant(), 1.0, 4e-15);
  EXPECT_MATRIX_NEAR(r * r.transpose(), Matrix3d::Identity(), 4e-15);
}

TEST(SO3, MatrixConstructorCarriesJetDerivativesAlongRotations) {
  // d/d(delta) of SO3(matrix(R exp(delta))).log() equals that of (R exp(delta)).log(),
  // including at the identity, where the matrix is exactly diagonal.
  using Jet = ceres::Jet<double, 3>;
  Random rng(17);
  std::vector<SO3d> rotations = {SO3d(), SO3d::exp(Vector3d(kPi / 2, 0, 0))};
  for (int k = 0; k < 10; ++k) rotations.push_back(SO3d::exp(rng.rotation_vector(3.0)));
  for (const SO3d& r : rotations) {
    Eigen::Matrix<Jet, 3, 1> delta;
    for (int i = 0; i < 3; ++i) delta(i) = Jet(0.0, i);
    const SO3<Jet> direct = r.cast<Jet>() * SO3<Jet>::exp(delta);
    const SO3<Jet> via_matrix(direct.matrix());
    const Eigen::Matrix<Jet, 3, 1> a = direct.log();
    const Eigen::Matrix<Jet, 3, 1> b = via_matrix.log();
    for (int i = 0; i < 3; ++i) {
      EXPECT_NEAR(a(i).a, b(i).a, 1e-14);
      EXPECT_MATRIX_NEAR(a(i).v, b(i).v, 1e-12);
    }
  }
}

TEST(SO3, RejectsZeroQuaternion) { EXPECT_THROW(SO3d(Eigen::Quaterniond(0.0, 0.0, 0.0, 0.0)), std::invalid_argument); }

TEST(SO3, RejectsNonFiniteQuaternion) {
  EXPECT_THROW(SO3d(Eigen::Quaterniond(NAN, 0.0, 0.0, 1.0)), std::invalid_argument);
  EXPECT_THROW(SO3d(Eigen::Quaterniond(INFINITY, 0.0, 0.0, 1.0)), std::invalid_argument);
}

TEST(SO3, RejectsNonFiniteMatrix) {
  Matrix3d m = Matrix3d::Identity();
  m(1, 2) = NAN;
  EXPECT_THROW(SO3d{m}, std::invalid_argument);
  m(1, 2) = INFINITY;
  EXPECT_THROW(SO3d{m}, std::invalid_argument);
}

TEST(SO3, CastChangesTheScalar) {
  Random rng(12);
  const SO3d r = SO3d::exp(rng.rotation_vector());
  const SO3f f = r.cast<float>();
  EXPECT_MATRIX_NEAR(f.matrix().cast<double>(), r.matrix(), 1e-6);
  using Jet = ceres::Jet<double, 3>;
  const SO3<Jet> j = r.cast<Jet>();
  // The cast renormalises in the new scalar type: equal to within rounding
  // (the last bit depends on the compiler's code for the Jet norm).
  for (int i = 0; i < 4; ++i) EXPECT_DOUBLE_EQ(j.data()[i].a, r.data()[i]);
}

// exp(omega + d) ~= exp(J_l d) exp(omega): with Jets, the derivative of
// log(exp(omega + d) exp(omega)^-1) at d = 0 is exactly J_l(omega).
TEST(SO3, LeftAndRightJacobiansMatchAutoDiff) {
  using Jet = ceres::Jet<double, 3>;
  Random rng(13);
  for (const double angle : stress_angles()) {
    for (int k = 0; k < 3; ++k) {
      const Vector3d omega = rng.unit_vector() * angle;
      Eigen::Matrix<Jet, 3, 1> omega_plus_d;
      for (int i = 0; i < 3; ++i) omega_plus_d(i) = Jet(omega(i), i);
      const SO3<Jet> r_inv = SO3d::exp(omega).inverse().cast<Jet>();
      const Eigen::Matrix<Jet, 3, 1> left = (SO3<Jet>::exp(omega_plus_d) * r_inv).log();
      const Eigen::Matrix<Jet, 3, 1> right = (r_inv * SO3<Jet>::exp(omega_plus_d)).log();
      Matrix3d d_left;
      Matrix3d d_right;
      for (int i = 0; i < 3; ++i) {
        d_left.row(i) = left(i).v.transpose();
        d_right.row(i) = right(i).v.transpose();
      }
      EXPECT_MATRIX_NEAR(d_left, SO3d::left_jacobian(omega), 1e-12) << "angle " << angle;
      EXPECT_MATRIX_NEAR(d_right, SO3d::right_jacobian(omega), 1e-12) << "angle " << angle;
    }
  }
}

TEST(SO3, LeftJacobianPredictsTheUpdateToSecondOrder) {
  Random rng(14);
  for (int k = 0; k < 100; ++k) {
    const Vector3d omega = rng.rotation_vector(3.0);
    const Vector3d d = rng.unit_vector() * 1e-5;
    const Vector3d left = (SO3d::exp(omega + d) * SO3d::exp(omega).inverse()).log();
    const Vector3d right = (SO3d::exp(omega).inverse() * SO3d::exp(omega + d)).log();
    EXPECT_MATRIX_NEAR(left, SO3d::left_jacobian(omega) * d, 1e-9);
    EXPECT_MATRIX_NEAR(right, SO3d::right_jacobian(omega) * d, 1e-9);
  }
}

TEST(SO3, JacobianIdentitiesAndInverses) {
  Random rng(15);
  for (const double angle : stress_angles()) {
    for (int k = 0; k < 3; ++k) {
      const Vector3d omega = rng.unit_vector() * angle;
      const Matrix3d jl = SO3d::left_jacobian(omega);
      const Matrix3d jr = SO3d::right_jacobian(omega);
      const Matrix3d r = SO3d::exp(omega).matrix();
      EXPECT_MATRIX_NEAR(jl * SO3d::left_jacobian_inverse(omega), Matrix3d::Identity(), 1e-14);
      EXPECT_MATRIX_NEAR(jr * SO3d::right_jacobian_inverse(omega), Matrix3d::Identity(), 1e-14);
      EXPECT_MATRIX_NEAR(jl, r * jr, 1e-14);         // J_l = R J_r
      EXPECT_MATRIX_NEAR(jl * omega, omega, 1e-14);  // the axis is fixed
      // J_l = int_0^1 exp(u hat(omega)) du = sum hat^n / (n+1)!, checked via
      // the exponential of the 4x4 [[hat, I], [0, 0]] block (its top-right is J_l).
      Eigen::Matrix<double, 6, 6> block = Eigen::Matrix<double, 6, 6>::Zero();
      block.topLeftCorner<3, 3>() = SO3d::hat(omega);
      block.topRightCorner<3, 3>() = Matrix3d::Identity();
      EXPECT_MATRIX_NEAR(jl, Matrix3d(test::expm_reference<6>(block).topRightCorner<3, 3>()), 1e-14);
    }
  }
}

TEST(SO3, LeftUpdatePointJacobianMatchesCentralDifferences) {
  Random rng(16);
  for (int k = 0; k < 50; ++k) {
    const SO3d r = SO3d::exp(rng.rotation_vector());
    const Vector3d p = rng.vector3(5.0);
    Matrix3d numeric;
    const double h = 1e-6;
    for (int i = 0; i < 3; ++i) {
      const Vector3d e = Vector3d::Unit(i) * h;
      numeric.col(i) = (SO3d::exp(e) * r * p - SO3d::exp(-e) * r * p) / (2 * h);
    }
    EXPECT_MATRIX_NEAR(r.left_update_point_jacobian(p), numeric, 1e-8);
  }
}

}  // namespace
}  // namespace facadeslam
