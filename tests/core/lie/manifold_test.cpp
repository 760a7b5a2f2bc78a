#include "core/lie/manifolds.hpp"

#include <cmath>

#include <ceres/autodiff_manifold.h>
#include <ceres/manifold_test_utils.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/core/lie/lie_test_utils.hpp"

namespace facadeslam {
namespace {

using Eigen::Vector3d;
using test::kPi;
using test::Random;
using Vector6d = Eigen::Matrix<double, 6, 1>;
using Vector7d = Eigen::Matrix<double, 7, 1>;
using Vector8d = Eigen::Matrix<double, 8, 1>;
using Vector = Eigen::VectorXd;
using Matrix = Eigen::MatrixXd;
// The matchers EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD names unqualified.
using ceres::HasCorrectMinusJacobianAt;
using ceres::HasCorrectPlusJacobianAt;
using ceres::HasCorrectRightMultiplyByPlusJacobianAt;
using ceres::MinusPlusIsIdentityAt;
using ceres::MinusPlusJacobianIsIdentityAt;
using ceres::PlusMinusIsIdentityAt;
using ceres::XMinusXIsZeroAt;
using ceres::XPlusZeroIsXAt;

Vector7d random_se3_params(Random& rng) {
  Vector7d x;
  x << rng.quaternion_coeffs(), rng.vector3(5.0);
  return x;
}

Vector8d random_sim3_params(Random& rng) {
  Vector8d x;
  x << rng.quaternion_coeffs(), rng.vector3(5.0), rng.uniform(-2.0, 2.0);
  return x;
}

Vector random_delta(Random& rng, int size, double rotation_size) {
  Vector d(size);
  d.head<3>() = rng.vector3(1.0);
  d.segment<3>(3) = rng.rotation_vector(rotation_size);
  if (size == 7) d(6) = rng.uniform(-1.0, 1.0);
  return d;
}

Vector plus(const ceres::Manifold& m, const Vector& x, const Vector& delta) {
  Vector out(m.AmbientSize());
  EXPECT_TRUE(m.Plus(x.data(), delta.data(), out.data()));
  return out;
}

Vector minus(const ceres::Manifold& m, const Vector& y, const Vector& x) {
  Vector out(m.TangentSize());
  EXPECT_TRUE(m.Minus(y.data(), x.data(), out.data()));
  return out;
}

Matrix plus_jacobian(const ceres::Manifold& m, const Vector& x) {
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> j(m.AmbientSize(), m.TangentSize());
  EXPECT_TRUE(m.PlusJacobian(x.data(), j.data()));
  return j;
}

Matrix minus_jacobian(const ceres::Manifold& m, const Vector& x) {
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> j(m.TangentSize(), m.AmbientSize());
  EXPECT_TRUE(m.MinusJacobian(x.data(), j.data()));
  return j;
}

// The invariants every manifold must satisfy, for one x and one delta.
void check_invariants(const ceres::Manifold& m, const Vector& x, const Vector& delta) {
  const int n = m.TangentSize();
  EXPECT_MATRIX_NEAR(plus(m, x, Vector::Zero(n)), x, 1e-15);
  EXPECT_MATRIX_NEAR(minus(m, x, x), Vector::Zero(n), 1e-14);  // round-off of t - R R^T t
  EXPECT_MATRIX_NEAR(minus(m, plus(m, x, delta), x), delta, 1e-12);
  // The quaternion Plus writes is unit.
  EXPECT_NEAR(plus(m, x, delta).head<4>().norm(), 1.0, 1e-15);

  // PlusJacobian and MinusJacobian against central differences.
  const double h = 1e-6;
  Matrix numeric_plus(m.AmbientSize(), n);
  for (int i = 0; i < n; ++i) {
    const Vector e = Vector::Unit(n, i) * h;
    numeric_plus.col(i) = (plus(m, x, e) - plus(m, x, -e)) / (2 * h);
  }
  EXPECT_MATRIX_NEAR(plus_jacobian(m, x), numeric_plus, 1e-8);
  Matrix numeric_minus(n, m.AmbientSize());
  for (int i = 0; i < m.AmbientSize(); ++i) {
    const Vector e = Vector::Unit(m.AmbientSize(), i) * h;
    numeric_minus.col(i) = (minus(m, x + e, x) - minus(m, x - e, x)) / (2 * h);
  }
  EXPECT_MATRIX_NEAR(minus_jacobian(m, x), numeric_minus, 1e-8);
  EXPECT_MATRIX_NEAR(minus_jacobian(m, x) * plus_jacobian(m, x), Matrix::Identity(n, n), 1e-14);
}

TEST(SE3Manifold, Sizes) {
  const SE3Manifold m;
  EXPECT_EQ(m.AmbientSize(), 7);
  EXPECT_EQ(m.TangentSize(), 6);
}

TEST(SE3Manifold, Invariants) {
  Random rng(61);
  const SE3Manifold m;
  for (int k = 0; k < 100; ++k) {
    const Vector x = random_se3_params(rng);
    check_invariants(m, x, random_delta(rng, 6, 0.5));
    check_invariants(m, x, random_delta(rng, 6, kPi - 1e-3));
    check_invariants(m, x, random_delta(rng, 6, 1e-6));
  }
}

TEST(SE3Manifold, CeresInvariantChecks) {
  // Ceres' own manifold test suite (Ridders numeric differentiation). y is
  // built as Plus(x, d) so that Plus(x, Minus(y, x)) reproduces y's quaternion
  // sign (Minus picks the shortest rotation; Plus cannot know y's sign).
  Random rng(62);
  const SE3Manifold manifold;
  for (int k = 0; k < 20; ++k) {
    const Vector x = random_se3_params(rng);
    const Vector delta = random_delta(rng, 6, 1.0);
    const Vector y = plus(manifold, x, random_delta(rng, 6, 2.0));
    constexpr double tolerance = 1e-9;
    EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD(manifold, x, delta, y, tolerance);
  }
}

TEST(SE3Manifold, PlusIsLeftMultiplicationByExp) {
  Random rng(63);
  const SE3Manifold m;
  const Vector x = random_se3_params(rng);
  const Vector delta = random_delta(rng, 6, 1.0);
  const SE3d expected = SE3d::exp(Vector6d(delta)) * se3_from_params(x.data());
  EXPECT_MATRIX_NEAR(se3_from_params(plus(m, x, delta).data()).matrix(), expected.matrix(), 1e-14);
  // And Minus is the log of y x^-1.
  const Vector y = random_se3_params(rng);
  const SE3d rel = se3_from_params(y.data()) * se3_from_params(x.data()).inverse();
  EXPECT_MATRIX_NEAR(minus(m, y, x), rel.log(), 1e-14);
}

TEST(SE3Manifold, MinusIgnoresTheQuaternionSigns) {
  Random rng(64);
  const SE3Manifold m;
  for (int k = 0; k < 50; ++k) {
    const Vector x = random_se3_params(rng);
    Vector y = random_se3_params(rng);
    const Vector d = minus(m, y, x);
    EXPECT_LE(d.tail<3>().norm(), kPi + 1e-15);
    y.head<4>() = -y.head<4>();
    EXPECT_MATRIX_NEAR(minus(m, y, x), d, 1e-14);
  }
}

// The SE3 manifold written once, generically, for ceres::AutoDiffManifold.
struct SE3PlusFunctor {
  template <class T>
  bool Plus(const T* x, const T* delta, T* x_plus_delta) const {
    se3_to_params(SE3<T>::exp(Eigen::Map<const Eigen::Matrix<T, 6, 1>>(delta)) * se3_from_params(x), x_plus_delta);
    return true;
  }
  template <class T>
  bool Minus(const T* y, const T* x, T* y_minus_x) const {
    Eigen::Map<Eigen::Matrix<T, 6, 1>> out(y_minus_x);
    out = (se3_from_params(y) * se3_from_params(x).inverse()).log();
    return true;
  }
};

TEST(SE3Manifold, MatchesAutoDiffManifold) {
  // The analytic PlusJacobian equals Ceres' auto-differentiation of the same
  // Plus written with SE3<Jet> (exercises exp with Jets at delta = 0).
  const ceres::AutoDiffManifold<SE3PlusFunctor, 7, 6> auto_diff;
  const SE3Manifold analytic;
  Random rng(65);
  for (int k = 0; k < 20; ++k) {
    const Vector x = random_se3_params(rng);
    EXPECT_MATRIX_NEAR(plus_jacobian(analytic, x), plus_jacobian(auto_diff, x), 1e-15);
    EXPECT_MATRIX_NEAR(minus_jacobian(analytic, x), minus_jacobian(auto_diff, x), 1e-14);
  }
}

TEST(SE3Manifold, RejectsAZeroQuaternion) {
  const SE3Manifold m;
  const Vector7d x = Vector7d::Zero();
  const Vector6d delta = Vector6d::Zero();
  Vector7d out;
  EXPECT_FALSE(m.Plus(x.data(), delta.data(), out.data()));
  Vector6d d;
  EXPECT_FALSE(m.Minus(x.data(), x.data(), d.data()));
}

TEST(SE3Manifold, RejectsNonFiniteValues) {
  const SE3Manifold m;
  Vector7d x;
  x << 0, 0, 0, 1, 0, 0, 0;
  Vector6d delta = Vector6d::Zero();
  Vector7d out;
  delta(2) = NAN;
  EXPECT_FALSE(m.Plus(x.data(), delta.data(), out.data()));
  Vector7d y = x;
  y(5) = INFINITY;
  Vector6d d;
  EXPECT_FALSE(m.Minus(y.data(), x.data(), d.data()));
}

TEST(SE3Manifold, PlusSucceedsForAHugeStep) {
  const SE3Manifold m;
  Vector7d x;
  x << 0, 0, 0, 1, 1, 2, 3;
  Vector6d delta;
  delta << 1e6, -2e6, 5e5, 400.0, -700.0, 300.0;
  Vector7d out;
  ASSERT_TRUE(m.Plus(x.data(), delta.data(), out.data()));
  EXPECT_TRUE(out.allFinite());
  EXPECT_NEAR(out.head<4>().norm(), 1.0, 1e-15);
}

TEST(Se3Params, LayoutIsEigenQuaternionThenTranslation) {
  Random rng(66);
  const SE3d pose = SE3d::exp((Vector6d() << rng.vector3(2.0), rng.rotation_vector()).finished());
  double params[kSe3ParamSize];
  se3_to_params(pose, params);
  const Eigen::Map<const Eigen::Quaterniond> q(params);
  EXPECT_MATRIX_NEAR(q.coeffs(), pose.unit_quaternion().coeffs(), 0.0);
  EXPECT_EQ(params[3], pose.unit_quaternion().w());
  EXPECT_MATRIX_NEAR(Vector3d(params[4], params[5], params[6]), pose.translation(), 0.0);
  // Reading renormalises the quaternion: the same pose to within rounding.
  EXPECT_MATRIX_NEAR(se3_from_params(params).matrix(), pose.matrix(), 1e-15);
}

TEST(Se3Params, ReadingNormalisesTheQuaternion) {
  const double params[kSe3ParamSize] = {0.0, 0.0, 0.0, 3.0, 1.0, 2.0, 3.0};
  const SE3d pose = se3_from_params(params);
  EXPECT_MATRIX_NEAR(pose.rotation_matrix(), Eigen::Matrix3d::Identity(), 0.0);
  EXPECT_MATRIX_NEAR(pose.translation(), Vector3d(1, 2, 3), 0.0);
}

TEST(Sim3Manifold, Sizes) {
  const Sim3Manifold m;
  EXPECT_EQ(m.AmbientSize(), 8);
  EXPECT_EQ(m.TangentSize(), 7);
}

TEST(Sim3Manifold, Invariants) {
  Random rng(71);
  const Sim3Manifold m;
  for (int k = 0; k < 100; ++k) {
    const Vector x = random_sim3_params(rng);
    check_invariants(m, x, random_delta(rng, 7, 0.5));
    check_invariants(m, x, random_delta(rng, 7, kPi - 1e-3));
    check_invariants(m, x, random_delta(rng, 7, 1e-6));
  }
}

TEST(Sim3Manifold, CeresInvariantChecks) {
  Random rng(72);
  const Sim3Manifold manifold;
  for (int k = 0; k < 20; ++k) {
    const Vector x = random_sim3_params(rng);
    const Vector delta = random_delta(rng, 7, 1.0);
    const Vector y = plus(manifold, x, random_delta(rng, 7, 2.0));
    constexpr double tolerance = 1e-9;
    EXPECT_THAT_MANIFOLD_INVARIANTS_HOLD(manifold, x, delta, y, tolerance);
  }
}

TEST(Sim3Manifold, PlusIsLeftMultiplicationByExp) {
  Random rng(73);
  const Sim3Manifold m;
  const Vector x = random_sim3_params(rng);
  const Vector delta = random_delta(rng, 7, 1.0);
  const Sim3d expected = Sim3d::exp(Vector7d(delta)) * sim3_from_params(x.data());
  const Sim3d actual = sim3_from_params(plus(m, x, delta).data());
  EXPECT_MATRIX_NEAR(actual.matrix(), expected.matrix(), 1e-13 * expected.scale());
  const Vector y = random_sim3_params(rng);
  const Sim3d rel = sim3_from_params(y.data()) * sim3_from_params(x.data()).inverse();
  EXPECT_MATRIX_NEAR(minus(m, y, x), rel.log(), 1e-13);
}

TEST(Sim3Manifold, RejectsAZeroQuaternion) {
  const Sim3Manifold m;
  const Vector8d x = Vector8d::Zero();
  const Vector7d delta = Vector7d::Zero();
  Vector8d out;
  EXPECT_FALSE(m.Plus(x.data(), delta.data(), out.data()));
  Vector7d d;
  EXPECT_FALSE(m.Minus(x.data(), x.data(), d.data()));
}

TEST(Sim3Manifold, RejectsNonFiniteValues) {
  const Sim3Manifold m;
  Vector8d x;
  x << 0, 0, 0, 1, 0, 0, 0, 0;
  Vector7d delta = Vector7d::Zero();
  Vector8d out;
  delta(6) = NAN;
  EXPECT_FALSE(m.Plus(x.data(), delta.data(), out.data()));
  delta(6) = 0.0;
  x(7) = INFINITY;
  EXPECT_FALSE(m.Plus(x.data(), delta.data(), out.data()));
}

TEST(Sim3Manifold, PlusSucceedsForAHugeStep) {
  // Ceres evaluates Plus(x, -gradient) and aborts the solve if it fails, so a
  // huge but finite step must succeed; the log-scale is added exactly.
  const Sim3Manifold m;
  Vector8d x;
  x << 0, 0, 0, 1, 1, 2, 3, 0.5;
  Vector7d delta;
  delta << 1e3, -2e3, 5e2, 40.0, -7.0, 3.0, 1e3;
  Vector8d out;
  ASSERT_TRUE(m.Plus(x.data(), delta.data(), out.data()));
  EXPECT_EQ(out(7), 1000.5);
  EXPECT_NEAR(out.head<4>().norm(), 1.0, 1e-15);
}

TEST(Sim3Params, LayoutEndsWithTheLogOfTheScale) {
  Random rng(74);
  const Sim3d s(SO3d::exp(rng.rotation_vector()), rng.vector3(2.0), 3.5);
  double params[kSim3ParamSize];
  sim3_to_params(s, params);
  const Eigen::Map<const Eigen::Quaterniond> q(params);
  EXPECT_MATRIX_NEAR(q.coeffs(), s.unit_quaternion().coeffs(), 0.0);
  EXPECT_MATRIX_NEAR(Vector3d(params[4], params[5], params[6]), s.translation(), 0.0);
  EXPECT_DOUBLE_EQ(params[7], std::log(3.5));
  const Sim3d back = sim3_from_params(params);
  EXPECT_NEAR(back.scale(), 3.5, 1e-15 * 3.5);
  EXPECT_MATRIX_NEAR(back.matrix(), s.matrix(), 1e-14);
}

}  // namespace
}  // namespace facadeslam
