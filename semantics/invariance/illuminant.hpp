#pragma once
// Illuminant colour change as a diagonal (von Kries) model (thesis III.4.3,
// eq. III.39): the picture taken under a black-body illuminant of K kelvin
// instead of 6500 K has each channel multiplied by its own gain.
//
// The linear-light gains are core/image/black_body.hpp's (the synthetic
// scenes use the same); the images here are 8-bit gamma-encoded (sRGB, gamma
// ~2.2), so a linear gain g multiplies the stored values by g^(1/2.2): still
// a diagonal model. At 3000 K about (R, G, B) x (1.24, 1, 0.68), at 10000 K
// about (0.94, 1, 1.11).
#include <opencv2/core.hpp>

#include "core/image/black_body.hpp"

namespace facadeslam::semantics {

inline constexpr double kReferenceKelvin = kReferenceIlluminantKelvin;

// Gains for the stored 8-bit values, in B, G, R order (OpenCV's channel
// order); (1, 1, 1) at 6500 K. Throws Error unless 500 <= kelvin <= 100000.
cv::Vec3d illuminant_gains_bgr(double kelvin);

}  // namespace facadeslam::semantics
