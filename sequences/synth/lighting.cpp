#include "sequences/synth/lighting.hpp"

#include <cmath>

#include "core/image/black_body.hpp"

namespace facadeslam::synth {

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

void apply_illumination(cv::Mat& colour, const Illumination& illumination) {
  CV_Assert(colour.type() == CV_32FC3);
  const cv::Vec3d gains = black_body_gains_bgr(illumination.temperature) * illumination.scale;
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
