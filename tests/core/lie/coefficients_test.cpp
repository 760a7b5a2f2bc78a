#include "core/lie/lie_coefficients.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <vector>

#include <ceres/jet.h>
#include <gtest/gtest.h>

namespace facadeslam {
namespace {

using Ld = long double;

// Long-double references: the power series sum_k (-1)^k theta^(2k) / (2k+n)!
// built term by term (independent of the hard-coded coefficients) below
// theta^2 = 1, the closed form above.
Ld alternating_series(Ld theta_sq, int n) {
  Ld factorial = 1;
  for (int i = 2; i <= n; ++i) factorial *= i;
  Ld term = 1 / factorial;  // k = 0
  Ld sum = term;
  for (int k = 1; k < 30; ++k) {
    term *= -theta_sq / ((2 * k + n - 1) * (2 * k + n));
    sum += term;
  }
  return sum;
}

Ld ref_b(Ld t) {  // (1 - cos theta) / theta^2
  return t < 1 ? alternating_series(t, 2) : (1 - std::cos(std::sqrt(t))) / t;
}
Ld ref_c(Ld t) {  // (theta - sin theta) / theta^3
  const Ld th = std::sqrt(t);
  return t < 1 ? alternating_series(t, 3) : (th - std::sin(th)) / (t * th);
}
Ld ref_d(Ld t) {  // (1 - (theta/2) cot(theta/2)) / theta^2
  // With 1 + cos = 2 - theta^2 B and sin/theta = 1 - theta^2 C this is
  // (B - 2C) / (2 (1 - theta^2 C)), free of cancellation near 0.
  if (t < 1) return (ref_b(t) - 2 * ref_c(t)) / (2 * (1 - t * ref_c(t)));
  const Ld half = std::sqrt(t) / 2;
  return (1 - half * std::cos(half) / std::sin(half)) / t;
}

Ld ref_sin_half_over_theta(Ld t) { return t == 0 ? 0.5L : std::sin(std::sqrt(t) / 2) / std::sqrt(t); }

std::vector<double> theta_values() {
  std::vector<double> out;
  for (double th = 1e-9; th < 3.14; th *= 1.37) out.push_back(th);
  for (const double th : {0.0, 9.999e-3, 1e-2, 1.0001e-2, 3.14159}) out.push_back(th);
  return out;
}

void expect_relative(double actual, Ld expected, double tol, const char* what, double theta) {
  EXPECT_LE(std::abs(static_cast<Ld>(actual) - expected), tol * std::abs(expected)) << what << " at theta " << theta;
}

TEST(LieCoefficients, MatchLongDoubleReferences) {
  for (const double th : theta_values()) {
    const double t = th * th;
    const Ld tl = static_cast<Ld>(th) * static_cast<Ld>(th);
    expect_relative(lie_detail::one_minus_cos_over_theta_sq(t), ref_b(tl), 4e-16, "B", th);
    expect_relative(lie_detail::theta_minus_sin_over_theta_cubed(t), ref_c(tl), 1e-15, "C", th);
    expect_relative(lie_detail::inverse_jacobian_coefficient(t), ref_d(tl), 1e-15, "D", th);
    const auto h = lie_detail::half_angle(t);
    expect_relative(h.cos_half, std::cos(std::sqrt(tl) / 2), 4e-16, "cos(theta/2)", th);
    expect_relative(h.sin_half_over_theta, ref_sin_half_over_theta(tl), 4e-16, "sin(theta/2)/theta", th);
  }
}

TEST(LieCoefficients, QuaternionLogFactorMatchesAtan2) {
  for (const double th : theta_values()) {
    if (th == 0.0) continue;
    const Ld half = static_cast<Ld>(th) / 2;
    const double n = static_cast<double>(std::sin(half));
    const double w = static_cast<double>(std::cos(half));
    const Ld expected = 2 * std::atan2(static_cast<Ld>(n), static_cast<Ld>(w)) / n;
    expect_relative(lie_detail::quaternion_log_factor(n * n, w), expected, 4e-16, "log factor", th);
  }
  EXPECT_DOUBLE_EQ(lie_detail::quaternion_log_factor(0.0, 1.0), 2.0);
}

// Value and derivative on both sides of a switch between series and closed
// form agree: a wrong series coefficient, or a closed form losing precision
// (in value or Jet derivative), shows up as a jump.
// value_tol is relative: a few ulps of round-off in either branch (the closed
// forms at theta = 1 still subtract numbers ~6x larger than their result),
// far below what a wrong series term would cause (> 1e-8 at theta = 1).
void expect_smooth_switch(const std::function<ceres::Jet<double, 1>(const ceres::Jet<double, 1>&)>& f, double at,
                          const char* name, double value_tol = 1e-14) {
  using Jet = ceres::Jet<double, 1>;
  // One ulp apart: `at` itself takes the closed form, its neighbour towards 0 the series.
  const Jet below = f(Jet(std::nextafter(at, 0.0), 0));
  const Jet above = f(Jet(at, 0));
  EXPECT_NEAR(below.a, above.a, value_tol * std::abs(below.a)) << name;
  EXPECT_NEAR(below.v(0), above.v(0), 1e-13 * std::abs(below.v(0))) << name;
}

TEST(LieCoefficients, SeriesAndClosedFormsJoinSmoothlyForJets) {
  using Jet = ceres::Jet<double, 1>;
  const double t = lie_detail::kSeriesAngleSq;
  expect_smooth_switch([](const Jet& x) { return lie_detail::one_minus_cos_over_theta_sq(x); }, t, "B");
  expect_smooth_switch([](const Jet& x) { return lie_detail::theta_minus_sin_over_theta_cubed(x); }, t, "C");
  expect_smooth_switch([](const Jet& x) { return lie_detail::inverse_jacobian_coefficient(x); }, t, "D");
  expect_smooth_switch([](const Jet& x) { return lie_detail::half_angle(x).cos_half; }, t, "cos");
  expect_smooth_switch([](const Jet& x) { return lie_detail::half_angle(x).sin_half_over_theta; }, t, "sin");
  for (const double sigma : {-3.0, -0.4, 0.0, 1e-7, 0.4, 3.0}) {
    // For sigma << -1 the closed forms lose ~eps sigma^2 / theta^2 (see sim3_w_coefficients).
    const double tol = 1e-14 * std::max(1.0, sigma * sigma);
    expect_smooth_switch([sigma](const Jet& x) { return lie_detail::sim3_w_coefficients(Jet(sigma), x).b; }, t,
                         "sim3 b", tol);
    expect_smooth_switch([sigma](const Jet& x) { return lie_detail::sim3_w_coefficients(Jet(sigma), x).c; }, t,
                         "sim3 c", tol);
  }
  // The quaternion log factor switches at n^2 = sin^2(theta/2) = kSeriesLogSq (w^2 = 1 - n^2).
  expect_smooth_switch(
      [](const Jet& n_sq) {
        return lie_detail::quaternion_log_factor(n_sq, Jet(std::sqrt(1 - lie_detail::kSeriesLogSq)));
      },
      lie_detail::kSeriesLogSq, "log factor");
  // The Sim3 moments switch from power series to recurrence at |sigma| = 1.
  for (const double edge : {-lie_detail::kSmallSigma, lie_detail::kSmallSigma}) {
    for (const double theta_sq : {0.0, 0.3, 0.99}) {
      expect_smooth_switch(
          [theta_sq](const Jet& sigma) { return lie_detail::sim3_w_coefficients(sigma, Jet(theta_sq)).b; }, edge,
          "sim3 b (sigma)");
      expect_smooth_switch(
          [theta_sq](const Jet& sigma) { return lie_detail::sim3_w_coefficients(sigma, Jet(theta_sq)).c; }, edge,
          "sim3 c (sigma)");
    }
  }
}

TEST(LieCoefficients, JetsAreFiniteAtZero) {
  using Jet = ceres::Jet<double, 1>;
  const Jet zero(0.0, 0);
  EXPECT_TRUE(std::isfinite(lie_detail::half_angle(zero).sin_half_over_theta.v(0)));
  EXPECT_NEAR(lie_detail::one_minus_cos_over_theta_sq(zero).v(0), -1.0 / 24.0, 1e-16);
  EXPECT_NEAR(lie_detail::theta_minus_sin_over_theta_cubed(zero).v(0), -1.0 / 120.0, 1e-16);
  EXPECT_NEAR(lie_detail::inverse_jacobian_coefficient(zero).v(0), 1.0 / 720.0, 1e-16);
  const auto w = lie_detail::sim3_w_coefficients(Jet(0.0, 0), Jet(0.0));
  EXPECT_NEAR(w.a.v(0), 0.5, 1e-16);  // d/dsigma (e^sigma - 1)/sigma at 0
}

TEST(LieCoefficients, ExpMomentsMatchQuadrature) {
  // M_k(sigma) = int_0^1 u^k e^(sigma u) du by composite Simpson in long double.
  constexpr int kK = lie_detail::kNumMoments;
  for (const double sigma : {-7.0, -1.0001, -0.9999, -1e-9, 0.0, 1e-6, 0.5, 0.9999, 1.0001, 4.0}) {
    const int n = 20000;
    std::array<Ld, kK> expected{};
    for (int i = 0; i <= n; ++i) {
      const Ld u = static_cast<Ld>(i) / n;
      const Ld weight = ((i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2)) * std::exp(sigma * u) / (3 * n);
      Ld power = 1;
      for (int k = 0; k < kK; ++k, power *= u) expected[k] += weight * power;
    }
    const auto m = lie_detail::exp_moments(sigma);
    for (int k = 0; k < kK; ++k) {
      // What the Sim3 series needs: M_k enters with weight theta^(k-1)/k! <= 1/k!.
      EXPECT_LE(std::abs(m[k] - expected[k]) * lie_detail::inverse_factorial(k), 1e-15 * expected[0])
          << "sigma " << sigma << " k " << k;
      // And in the power-series range every moment is accurate by itself.
      if (std::abs(sigma) < lie_detail::kSmallSigma && k <= 8) {
        EXPECT_LE(std::abs(m[k] - expected[k]), 1e-14 * expected[k]) << "sigma " << sigma << " k " << k;
      }
    }
  }
}

}  // namespace
}  // namespace facadeslam
