#pragma once
// A smooth random colour texture: random blocks of 8x8 pixels, bicubically
// enlarged, so FAST finds corners everywhere. Shown to the tracker as flat
// frames it can never initialise on (no parallax), which is what the CLI
// tests of replay's failure paths need.
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

namespace facadeslam::test {

inline cv::Mat smooth_random_texture(int width, int height, unsigned seed) {
  cv::Mat noise(height / 8, width / 8, CV_8UC3);
  cv::RNG rng(seed);
  rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
  cv::Mat image;
  cv::resize(noise, image, {width, height}, 0, 0, cv::INTER_CUBIC);
  return image;
}

}  // namespace facadeslam::test
