#pragma once
// Shared helpers for the Lie group tests: seeded random elements, the
// rotation angles that stress the closed forms, an independent matrix
// exponential in long double, and matrix comparisons.
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <Eigen/Core>

namespace facadeslam::test {

inline constexpr double kPi = std::numbers::pi;

// Angles near 0, around the series switches (theta = 1, and theta = 0.6435
// where sin^2(theta/2) = 0.1 for the quaternion log), generic, and near pi.
inline std::vector<double> stress_angles() {
  return {0.0,   1e-12, 1e-9, 1e-6,  1e-4, 1e-2, 0.1,        0.5,        0.643,      0.6435011087932844,
          0.644, 0.999, 1.0,  1.001, 2.0,  3.0,  kPi - 1e-3, kPi - 1e-6, kPi - 1e-9, kPi};
}

class Random {
 public:
  explicit Random(unsigned seed = 12345) : engine_(seed) {}

  double uniform(double lo, double hi) { return std::uniform_real_distribution<double>(lo, hi)(engine_); }

  // Vectors are drawn one entry a statement, in index order: as the
  // arguments of one call they would be drawn in the compiler's order (GCC
  // right to left, clang left to right), and the tests' data with them.
  Eigen::Vector3d unit_vector() {
    std::normal_distribution<double> n(0.0, 1.0);
    Eigen::Vector3d v;
    do {
      for (int i = 0; i < 3; ++i) v[i] = n(engine_);
    } while (v.norm() < 1e-3);
    return v.normalized();
  }

  Eigen::Vector3d vector3(double half_range) {
    Eigen::Vector3d v;
    for (int i = 0; i < 3; ++i) v[i] = uniform(-half_range, half_range);
    return v;
  }

  // A uniformly random rotation vector with |omega| < max_angle.
  Eigen::Vector3d rotation_vector(double max_angle = kPi) { return unit_vector() * uniform(0.0, max_angle); }

  // A uniformly distributed unit quaternion (either sign), as coefficients [x y z w].
  Eigen::Vector4d quaternion_coeffs() {
    std::normal_distribution<double> n(0.0, 1.0);
    Eigen::Vector4d q;
    do {
      for (int i = 0; i < 4; ++i) q[i] = n(engine_);
    } while (q.norm() < 1e-3);
    return q.normalized();
  }

 private:
  std::mt19937 engine_;
};

// exp(X) = sum_k X^k / k! in long double with scaling and squaring; an
// independent reference for the closed forms (valid for moderate |X|).
template <int N>
Eigen::Matrix<double, N, N> expm_reference(const Eigen::Matrix<double, N, N>& x) {
  using MatrixL = Eigen::Matrix<long double, N, N>;
  MatrixL a = x.template cast<long double>();
  int squarings = 0;
  while (a.cwiseAbs().maxCoeff() > 0.5L) {
    a /= 2.0L;
    ++squarings;
  }
  MatrixL result = MatrixL::Identity();
  MatrixL term = MatrixL::Identity();
  for (int k = 1; k < 40; ++k) {
    term = term * a / static_cast<long double>(k);
    result += term;
  }
  for (int i = 0; i < squarings; ++i) result = result * result;
  return result.template cast<double>();
}

template <class A, class B>
double max_abs_diff(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b) {
  return (a - b).cwiseAbs().maxCoeff();
}

// Entry-wise |a - b| <= tol, with both matrices in the failure message.
template <class A, class B>
::testing::AssertionResult matrix_near(const Eigen::MatrixBase<A>& a, const Eigen::MatrixBase<B>& b, double tol) {
  const double diff = max_abs_diff(a, b);
  if (diff <= tol) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << "max |a - b| = " << diff << " > " << tol << "\na:\n" << a << "\nb:\n" << b;
}

}  // namespace facadeslam::test

// EXPECT that two matrices agree entry-wise to an absolute tolerance; more
// context can be streamed with <<. Wrap arguments holding template commas
// (m.block<3, 3>()) in parentheses.
#define EXPECT_MATRIX_NEAR(a, b, tol) EXPECT_TRUE(::facadeslam::test::matrix_near((a), (b), (tol)))
