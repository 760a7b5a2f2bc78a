#include "semantics/invariance/illuminant.hpp"

#include <cmath>

#include "core/image/black_body.hpp"

namespace facadeslam::semantics {
namespace {

constexpr double kGamma = 2.2;

}  // namespace

cv::Vec3d illuminant_gains_bgr(double kelvin) {
  const cv::Vec3d linear = black_body_gains_bgr(kelvin);
  cv::Vec3d gains;
  for (int c = 0; c < 3; ++c) gains[c] = std::pow(linear[c], 1.0 / kGamma);
  return gains;
}

}  // namespace facadeslam::semantics
