#include "semantics/invariance/illuminant.hpp"

#include <cmath>

#include "core/util/error.hpp"

namespace facadeslam::semantics {
namespace {

constexpr double kSecondRadiationConstant = 1.4388e-2;  // m K
constexpr double kGamma = 2.2;
// Dominant wavelengths of the sRGB primaries, in B, G, R order.
constexpr double kWavelengthBgr[3] = {464e-9, 549e-9, 611e-9};

// Planck's law without the constant factor (it cancels in the ratios).
double black_body(double wavelength, double kelvin) {
  return std::pow(wavelength, -5.0) / std::expm1(kSecondRadiationConstant / (wavelength * kelvin));
}

}  // namespace

cv::Vec3d illuminant_gains_bgr(double kelvin) {
  if (!(kelvin >= 500.0 && kelvin <= 100000.0))
    throw Error("illuminant: the colour temperature must be between 500 and 100000 K");
  cv::Vec3d linear;
  for (int c = 0; c < 3; ++c)
    linear[c] = black_body(kWavelengthBgr[c], kelvin) / black_body(kWavelengthBgr[c], kReferenceKelvin);
  cv::Vec3d gains;
  for (int c = 0; c < 3; ++c) gains[c] = std::pow(linear[c] / linear[1], 1.0 / kGamma);
  return gains;
}

}  // namespace facadeslam::semantics
