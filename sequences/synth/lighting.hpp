#pragma once
// Lighting that changes over a sequence, by the diagonal model the thesis
// uses for its invariance tests (III.4.3, after van de Sande et al. 2010):
//   intensity scale        c' = a c
//   intensity shift        c' = c + o1
//   illuminant colour      c' = diag(g_r, g_g, g_b) c
// combined here as c'_k = a g_k c_k + o1 for each channel k, applied to the
// rendered 8-bit-range values before noise and quantisation.
//
// The colour-temperature gains are core/image/black_body.hpp's: the rendered
// values are linear light, so they apply as they are.
#include <vector>

#include <opencv2/core.hpp>

#include "sequences/synth/scene.hpp"

namespace facadeslam::synth {

struct Illumination {
  double scale = 1.0;
  double shift = 0.0;
  double temperature = 6500.0;
};

// The illumination at time t: keys interpolated linearly (temperature in
// mireds, 1e6 / T, which is how colour temperature changes perceptually
// evenly), held constant before the first and after the last key; neutral
// when there are no keys.
Illumination illumination_at(const std::vector<LightingKey>& keys, double t);

// c'_k = scale g_k c_k + shift on a CV_32FC3 BGR image, in place, with the
// gains g of black_body_gains_bgr(temperature).
void apply_illumination(cv::Mat& colour, const Illumination& illumination);

}  // namespace facadeslam::synth
