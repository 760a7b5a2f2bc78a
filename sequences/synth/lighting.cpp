#include "sequences/synth/lighting.hpp"

#include <cmath>

namespace facadeslam::synth {
namespace {

constexpr double kReferenceTemperature = 6500.0;

// Planck's law without the constant factors that cancel in a ratio at one
// wavelength: 1 / (exp(c2 / (lambda T)) - 1), c2 = h c / k_B.
double relative_radiance(double wavelength_m, double temperature) {
  constexpr double c2 = 1.438776877e-2;  // m K
  return 1.0 / std::expm1(c2 / (wavelength_m * temperature));
}

}  // namespace

Illumination illumination_at(const std::vector<LightingKey>& keys, double t) {
  if (keys.empty()) return {};
  const auto from_key = [](const LightingKey& k) { return Illumination{k.scale, k.shift, k.temperature}; };
  if (t <= keys.front().time) return from_key(keys.front());
  if (t >= keys.back().time) return from_key(keys.back());
  std::size_t i = 0;
  while (keys[i + 1].time < t) ++i;
  const LightingKey& a = keys[i];
  const LightingKey& b = keys[i + 1];
  const double w = (t - a.time) / (b.time - a.time);
  const double mired = (1.0 - w) * 1e6 / a.temperature + w * 1e6 / b.temperature;
  return {(1.0 - w) * a.scale + w * b.scale, (1.0 - w) * a.shift + w * b.shift, 1e6 / mired};
}

cv::Vec3d illuminant_gains_bgr(double temperature) {
  const double wavelengths_bgr[] = {465e-9, 550e-9, 610e-9};
  cv::Vec3d ratio;
  for (int k = 0; k < 3; ++k)
    ratio[k] = relative_radiance(wavelengths_bgr[k], temperature) /
               relative_radiance(wavelengths_bgr[k], kReferenceTemperature);
  return ratio / ratio[1];
}

void apply_illumination(cv::Mat& colour, const Illumination& illumination) {
  CV_Assert(colour.type() == CV_32FC3);
  const cv::Vec3d gains = illuminant_gains_bgr(illumination.temperature) * illumination.scale;
  const float g[3] = {static_cast<float>(gains[0]), static_cast<float>(gains[1]), static_cast<float>(gains[2])};
  const float shift = static_cast<float>(illumination.shift);
  for (int y = 0; y < colour.rows; ++y) {
    float* p = colour.ptr<float>(y);
    for (int x = 0; x < colour.cols * 3; x += 3) {
      p[x] = g[0] * p[x] + shift;
      p[x + 1] = g[1] * p[x + 1] + shift;
      p[x + 2] = g[2] * p[x + 2] + shift;
    }
  }
}

}  // namespace facadeslam::synth
