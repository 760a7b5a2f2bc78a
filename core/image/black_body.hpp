#pragma once
// Illuminant colour as a diagonal (von Kries) model, thesis III.4.3: a scene
// lit by a black body of T kelvin instead of the 6500 K reference has each
// camera channel multiplied by its own gain. One shared approximation for
// the synthetic scenes' lighting (sequences/synth/lighting) and the
// invariance cases (semantics/invariance/illuminant):
//  - each channel responds at one wavelength, the dominant wavelength of the
//    sRGB primary (R 611 nm, G 549 nm, B 464 nm);
//  - a black body's radiance there follows Planck's law,
//    B(l, T) ~ l^-5 / (exp(c2 / (l T)) - 1), c2 = h c / k_B;
//  - the gain of a channel is B(l, T) / B(l, 6500), divided by green's so that
//    brightness stays about the same (intensity is changed on its own).
// 3800 K gives about (R, G, B) x (1.33, 1, 0.60); 10000 K about (0.88, 1, 1.27).
#include <opencv2/core.hpp>

namespace facadeslam {

inline constexpr double kReferenceIlluminantKelvin = 6500.0;

// Linear-light gains in B, G, R order (OpenCV's channel order); (1, 1, 1)
// at 6500 K. Throws Error unless 500 <= kelvin <= 100000.
cv::Vec3d black_body_gains_bgr(double kelvin);

}  // namespace facadeslam
