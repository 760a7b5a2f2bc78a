#include "core/image/black_body.hpp"

#include <cmath>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

constexpr double kSecondRadiationConstant = 1.438776877e-2;  // c2 = h c / k_B, m K
constexpr double kWavelengthBgr[3] = {464e-9, 549e-9, 611e-9};

// Planck's law without the constant factor (it cancels in the ratios).
double radiance(double wavelength, double kelvin) {
  return std::pow(wavelength, -5.0) / std::expm1(kSecondRadiationConstant / (wavelength * kelvin));
}

}  // namespace

cv::Vec3d black_body_gains_bgr(double kelvin) {
  if (!(kelvin >= 500.0 && kelvin <= 100000.0))
    throw Error("illuminant: the colour temperature must be between 500 and 100000 K");
  cv::Vec3d ratio;
  for (int c = 0; c < 3; ++c)
    ratio[c] = radiance(kWavelengthBgr[c], kelvin) / radiance(kWavelengthBgr[c], kReferenceIlluminantKelvin);
  return ratio / ratio[1];
}

}  // namespace facadeslam
