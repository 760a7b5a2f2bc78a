#pragma once
// Tukey's biweight M-estimator with a robust scale, as the tracker's pose
// update uses it (PTAM's Tukey class), on SQUARED residual norms.
//
// Scale: for residuals r in R^2 with independent N(0, sigma^2) components,
// |r|^2 / sigma^2 is chi-square with 2 degrees of freedom, whose median is
// 2 ln 2. Hence sigma^2 = median(|r|^2) / (2 ln 2), which the gross outliers
// (fewer than half) cannot move far. PTAM instead takes
// sigma = 1.4826 sqrt(median |r|^2), the 1-D MAD rule applied to a 2-D norm,
// which inflates sigma^2 by 3x (a more lenient cut); set
// median_to_sigma_squared = 1.4826^2 to reproduce it.
// A floor (min_sigma_squared) keeps exact or near-exact data from declaring
// every tiny residual an outlier.
//
// Weight: w(|r|^2) = (1 - |r|^2 / (c sigma)^2)^2 inside the cut, 0 outside,
// with c = 4.685 (95% efficiency under Gaussian noise).
#include <span>

namespace facadeslam {

inline constexpr double kTukeyC = 4.685;
inline constexpr double kMedianToSigmaSquared2d = 0.72134752044448170;  // 1 / (2 ln 2)

// Robust sigma^2 from squared residual norms; reorders `squared_errors`.
// Returns min_sigma_squared for an empty input.
double robust_sigma_squared(std::span<double> squared_errors, double min_sigma_squared,
                            double median_to_sigma_squared = kMedianToSigmaSquared2d);

// Tukey biweight for a squared residual given the squared cut (c sigma)^2.
inline double tukey_weight(double squared_error, double squared_cut) {
  if (!(squared_error < squared_cut)) return 0.0;
  const double u = 1.0 - squared_error / squared_cut;
  return u * u;
}

}  // namespace facadeslam
