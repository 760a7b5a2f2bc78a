#pragma once
// Illuminant colour change as a diagonal (von Kries) model (thesis III.4.3,
// eq. III.39): the picture taken under a black-body illuminant of K kelvin
// instead of 6500 K has each channel multiplied by its own gain.
//
// The gains are a short approximation, not a colorimetric table:
//  - each camera channel is taken to respond at one wavelength, the dominant
//    wavelength of the sRGB primary (R 611 nm, G 549 nm, B 464 nm);
//  - the light of a black body at that wavelength follows Planck's law,
//    B(l, T) ~ l^-5 / (exp(c2 / (l T)) - 1), c2 = hc/k = 1.4388e-2 m K;
//  - the linear gain of a channel is B(l, K) / B(l, 6500), divided by the
//    green channel's so that brightness stays about the same (the intensity
//    cases test brightness on their own);
//  - the images are 8-bit gamma-encoded (sRGB, gamma ~2.2), so a linear gain
//    g multiplies the stored values by g^(1/2.2): still a diagonal model.
// At 3000 K this gives about (R, G, B) x (1.24, 1, 0.68), at 10000 K about
// (0.94, 1, 1.11): warm and cold light, as expected.
#include <opencv2/core.hpp>

namespace facadeslam::semantics {

inline constexpr double kReferenceKelvin = 6500.0;

// Gains for the stored 8-bit values, in B, G, R order (OpenCV's channel
// order); (1, 1, 1) at 6500 K. Throws Error unless 500 <= kelvin <= 100000.
cv::Vec3d illuminant_gains_bgr(double kelvin);

}  // namespace facadeslam::semantics
