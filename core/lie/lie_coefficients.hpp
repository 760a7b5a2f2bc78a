#pragma once
// Scalar coefficient functions behind the closed forms of SO3, SE3 and Sim3.
//
// Each function has a closed form and a Taylor series, used below a switch:
//  * the closed forms divide by theta (0/0 at the identity), and with
//    ceres::Jet scalars sqrt(theta^2) has an infinite derivative at 0, so
//    the identity must never reach a closed form;
//  * closed forms with a subtraction ((theta - sin theta) / theta^3, ...)
//    lose about eps / theta^2 of relative precision, and the Jet derivatives
//    of all of them (even sin(theta/2)/theta) about eps / theta^2 too, since
//    the derivative of f(sqrt(t)) / sqrt(t) subtracts two O(1/t) terms.
// So every coefficient switches at theta = 1 rad (quaternion log: at
// sin^2(theta/2) = 0.1), where those losses are a few ulps, and below uses a
// series truncated where the first dropped term is below 1e-18 relative.
// Every value and first derivative is thus accurate to a few ulps.
//
// Everything is templated on the scalar and uses only arithmetic,
// comparisons and math functions that ceres::Jet provides, so Ceres can
// auto-differentiate through it (comparisons use the Jet's value part).
// Series coefficients are generated at compile time from their general term,
// not typed in.
#include <array>
#include <cmath>
#include <cstddef>

namespace facadeslam::lie_detail {

// theta^2 below which the coefficients use their series.
inline constexpr double kSeriesAngleSq = 1.0;
// sin^2(theta/2) below which the quaternion log factor uses its series.
inline constexpr double kSeriesLogSq = 0.1;
// |sigma| below which the Sim3 moments use their power series rather than the
// upward recurrence (whose absolute error grows like k! / |sigma|^k).
inline constexpr double kSmallSigma = 1.0;

inline constexpr int kSeriesTerms = 10;     // in theta^2 < 1: 1/(2*10+2)! < 1e-18
inline constexpr int kLogSeriesTerms = 20;  // in x^2 < 1/9: x^40 / 41 < 1e-20

// 1 / n!
constexpr double inverse_factorial(int n) {
  double f = 1.0;
  for (int i = 2; i <= n; ++i) f *= i;
  return 1.0 / f;
}

// c_k = (-1)^k ratio^k / (2k + n)!: the series of sin, cos and their relatives in t = theta^2.
template <int K>
constexpr std::array<double, K> alternating_factorial_series(int n, double ratio = 1.0) {
  std::array<double, K> c{};
  double sign_power = 1.0;
  for (int k = 0; k < K; ++k) {
    c[k] = sign_power * inverse_factorial(2 * k + n);
    sign_power *= -ratio;
  }
  return c;
}

// Horner evaluation of c[0] + c[1] x + c[2] x^2 + ..., with the double
// coefficients lifted to T so that Jet scalars work.
template <class T, std::size_t N>
T polynomial(const T& x, const std::array<double, N>& c) {
  T result = T(c[N - 1]);
  for (std::size_t i = N - 1; i-- > 0;) result = T(c[i]) + x * result;
  return result;
}

// Unit quaternion of exp(omega): w = cos(theta/2), xyz = sin(theta/2)/theta * omega.
template <class T>
struct HalfAngle {
  T cos_half;             // cos(theta / 2)
  T sin_half_over_theta;  // sin(theta / 2) / theta
};

template <class T>
HalfAngle<T> half_angle(const T& theta_sq) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (theta_sq < T(kSeriesAngleSq)) {
    // cos(theta/2)         = sum_k (-1)^k (theta^2/4)^k / (2k)!
    // sin(theta/2) / theta = (1/2) sum_k (-1)^k (theta^2/4)^k / (2k+1)!
    static constexpr auto kCos = alternating_factorial_series<kSeriesTerms>(0, 0.25);
    static constexpr auto kSin = alternating_factorial_series<kSeriesTerms>(1, 0.25);
    return {polynomial(theta_sq, kCos), T(0.5) * polynomial(theta_sq, kSin)};
  }
  const T theta = sqrt(theta_sq);
  const T half = T(0.5) * theta;
  return {cos(half), sin(half) / theta};
}

// B(theta) = (1 - cos theta) / theta^2, evaluated as 2 sin^2(theta/2) / theta^2
// (no cancellation). Coefficient of hat(omega) in the SO3 left
// Jacobian.
template <class T>
T one_minus_cos_over_theta_sq(const T& theta_sq) {
  using std::sin;
  using std::sqrt;
  if (theta_sq < T(kSeriesAngleSq)) {
    static constexpr auto kB = alternating_factorial_series<kSeriesTerms>(2);  // (-1)^k / (2k+2)!
    return polynomial(theta_sq, kB);
  }
  const T s = sin(T(0.5) * sqrt(theta_sq));
  return T(2) * s * s / theta_sq;
}

// C(theta) = (theta - sin theta) / theta^3. Coefficient of hat(omega)^2 in
// the SO3 left Jacobian.
template <class T>
T theta_minus_sin_over_theta_cubed(const T& theta_sq) {
  using std::sin;
  using std::sqrt;
  if (theta_sq < T(kSeriesAngleSq)) {
    static constexpr auto kC = alternating_factorial_series<kSeriesTerms>(3);  // (-1)^k / (2k+3)!
    return polynomial(theta_sq, kC);
  }
  const T theta = sqrt(theta_sq);
  return (theta - sin(theta)) / (theta_sq * theta);
}

// D(theta) = (1 - (theta/2) cot(theta/2)) / theta^2
//          = 1/theta^2 - (1 + cos theta) / (2 theta sin theta).
// Coefficient of hat(omega)^2 in the inverse SO3 left Jacobian. Written with
// cot(theta/2) it stays finite at theta = pi (where sin theta = 0); it is
// singular only at theta = 2 pi. Series: with 1 + cos = 2 - theta^2 B and
// sin(theta)/theta = 1 - theta^2 C, D = (B - 2C) / (2 sin(theta)/theta), and
// B - 2C = sum_k (-1)^k (2k+1) theta^(2k) / (2k+3)!.
template <class T>
T inverse_jacobian_coefficient(const T& theta_sq) {
  using std::cos;
  using std::sin;
  using std::sqrt;
  if (theta_sq < T(kSeriesAngleSq)) {
    static constexpr auto kNumerator = [] {
      auto c = alternating_factorial_series<kSeriesTerms>(3);
      for (int k = 0; k < kSeriesTerms; ++k) c[k] *= 2 * k + 1;
      return c;
    }();
    static constexpr auto kSinc = alternating_factorial_series<kSeriesTerms>(1);  // sin(theta)/theta
    return polynomial(theta_sq, kNumerator) / (T(2) * polynomial(theta_sq, kSinc));
  }
  const T half = T(0.5) * sqrt(theta_sq);
  return (T(1) - half * cos(half) / sin(half)) / theta_sq;
}

// Ratio theta / sin(theta/2) for the SO3 logarithm of the unit quaternion
// (w, v), with w >= 0, n = |v| = sin(theta/2), theta = 2 atan2(n, w):
// omega = [2 atan2(n, w) / n] v. atan2 stays well conditioned for every
// angle, including theta -> pi (w -> 0), unlike acos of the trace.
template <class T>
T quaternion_log_factor(const T& n_sq, const T& w) {
  using std::atan2;
  using std::sqrt;
  if (n_sq < T(kSeriesLogSq)) {
    // 2 atan(x) / (x w) with x = n / w: (2 / w) sum_k (-1)^k x^(2k) / (2k + 1)
    static constexpr auto kAtan = [] {
      std::array<double, kLogSeriesTerms> c{};
      for (int k = 0; k < kLogSeriesTerms; ++k) c[k] = (k % 2 ? -1.0 : 1.0) / (2 * k + 1);
      return c;
    }();
    return T(2) / w * polynomial(n_sq / (w * w), kAtan);
  }
  const T n = sqrt(n_sq);
  return T(2) * atan2(n, w) / n;
}

// Moments M_k(sigma) = int_0^1 u^k e^(sigma u) du for k = 0..20.
// Small |sigma|: power series M_k = sum_j sigma^j / (j! (k + j + 1)) (20
// terms: the first dropped one is below 1e-18 relative). Otherwise
// M_0 = expm1(sigma)/sigma and M_k = (e^sigma - k M_(k-1)) / sigma
// (integration by parts). The recurrence's absolute error grows like
// k! / |sigma|^k, but M_k only enters the Sim3 series with weight
// theta^(k-1) / k! (theta < 1), so every term stays accurate to eps there.
inline constexpr int kNumMoments = 2 * kSeriesTerms + 1;
inline constexpr int kMomentSeriesTerms = 20;

template <class T, int N>
std::array<T, N> exp_moments_up_to(const T& sigma) {
  using std::abs;
  using std::exp;
  using std::expm1;
  std::array<T, N> m;
  if (abs(sigma) < T(kSmallSigma)) {
    for (auto& mk : m) mk = T(0);
    T term = T(1);  // sigma^j / j!
    for (int j = 0; j < kMomentSeriesTerms; ++j) {
      for (int k = 0; k < N; ++k) m[k] += term / T(double(k + j + 1));
      term = term * sigma / T(double(j + 1));
    }
    return m;
  }
  m[0] = expm1(sigma) / sigma;
  if constexpr (N > 1) {
    const T e = exp(sigma);
    for (int k = 1; k < N; ++k) m[k] = (e - T(double(k)) * m[k - 1]) / sigma;
  }
  return m;
}

template <class T>
std::array<T, kNumMoments> exp_moments(const T& sigma) {
  return exp_moments_up_to<T, kNumMoments>(sigma);
}

// Coefficients of the Sim3 translation matrix
//   W(omega, sigma) = int_0^1 e^(sigma u) exp(u hat(omega)) du = A I + B hat(omega) + C
//   hat(omega)^2.
// With exp(u hat) = I + sin(u theta)/theta hat + (1 - cos(u theta))/theta^2 hat^2:
//   A = int e^(sigma u) du = (e^sigma - 1) / sigma
//   B = (1/theta)   int e^(sigma u) sin(u theta) du
//   C = (1/theta^2) int e^(sigma u) (1 - cos(u theta)) du
// Closed form from int_0^1 e^((sigma + i theta) u) du = (e^(sigma + i theta) - 1) / (sigma + i
// theta). At sigma = 0 they reduce to the SO3 left Jacobian's (1, B(theta), C(theta)). Series below
// theta = 1 rad, closed form above. (For sigma << -1 the weight e^(sigma u) sits near u = 0, where
// the effective angle is theta / |sigma|: there the closed-form B and C lose ~eps sigma^2 / theta^2
// relative, yet their terms in W, B hat and C hat^2, stay accurate to eps |W|.)
template <class T>
struct Sim3Coefficients {
  T a;
  T b;
  T c;
};

template <class T>
Sim3Coefficients<T> sim3_w_coefficients(const T& sigma, const T& theta_sq) {
  using std::cos;
  using std::exp;
  using std::expm1;
  using std::sin;
  using std::sqrt;
  if (theta_sq < T(kSeriesAngleSq)) {
    const std::array<T, kNumMoments> m = exp_moments(sigma);
    // Expanding sin and 1 - cos under the integral:
    //   B = sum_k (-1)^k theta^(2k) M_(2k+1) / (2k+1)!
    //   C = sum_k (-1)^k theta^(2k) M_(2k+2) / (2k+2)!
    static constexpr auto kB = alternating_factorial_series<kSeriesTerms>(1);
    static constexpr auto kC = alternating_factorial_series<kSeriesTerms>(2);
    T b = T(kB[kSeriesTerms - 1]) * m[2 * kSeriesTerms - 1];
    T c = T(kC[kSeriesTerms - 1]) * m[2 * kSeriesTerms];
    for (int k = kSeriesTerms - 1; k-- > 0;) {
      b = T(kB[k]) * m[2 * k + 1] + theta_sq * b;
      c = T(kC[k]) * m[2 * k + 2] + theta_sq * c;
    }
    return {m[0], b, c};
  }
  const T a = exp_moments_up_to<T, 1>(sigma)[0];
  const T theta = sqrt(theta_sq);
  const T half_sin = sin(T(0.5) * theta);
  // e^sigma cos(theta) - 1, without cancellation when sigma is small.
  const T re_minus_one = expm1(sigma) * cos(theta) - T(2) * half_sin * half_sin;
  const T im = exp(sigma) * sin(theta);
  const T denominator = sigma * sigma + theta_sq;
  const T integral_cos = (sigma * re_minus_one + theta * im) / denominator;
  const T integral_sin = (sigma * im - theta * re_minus_one) / denominator;
  return {a, integral_sin / theta, (a - integral_cos) / theta_sq};
}

}  // namespace facadeslam::lie_detail
