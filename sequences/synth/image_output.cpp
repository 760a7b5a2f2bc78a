#include "sequences/synth/image_output.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "sequences/synth/deterministic_random.hpp"

namespace facadeslam::synth {

namespace {

// The standard normal quantiles of 65536 equally likely bins,
// Phi^-1((k + 0.5) / 65536): a 16-bit random index then gives a normal
// deviate (to 1/65536 in probability, far finer than 8-bit output needs)
// without a logarithm or cosine per value.
std::vector<float> build_normal_quantiles() {
  std::vector<float> table(65536);
  for (std::size_t k = 0; k < table.size(); ++k) {
    const double p = (static_cast<double>(k) + 0.5) / 65536.0;
    // Bisection on Phi(x) = erfc(-x / sqrt 2) / 2, monotonic in x.
    double lo = -6.0, hi = 6.0;
    for (int i = 0; i < 60; ++i) {
      const double mid = 0.5 * (lo + hi);
      (0.5 * std::erfc(-mid / std::numbers::sqrt2) < p ? lo : hi) = mid;
    }
    table[k] = static_cast<float>(0.5 * (lo + hi));
  }
  return table;
}

// Held in a vector, not a std::array filled by a lambda: GCC tries to
// constant-evaluate the latter at compile time (3.9 M erfc calls, 100 s of
// compile time) before giving up.
const std::vector<float>& normal_quantiles() {
  static const std::vector<float> table = build_normal_quantiles();
  return table;
}

}  // namespace

void add_pixel_noise(cv::Mat& colour, double sigma, std::uint64_t seed, int frame) {
  CV_Assert(colour.type() == CV_32FC3);
  if (sigma <= 0.0) return;
  const auto& quantiles = normal_quantiles();
  const std::uint64_t frame_key = hash64(seed, 0x4015Eull, static_cast<std::uint64_t>(frame));
  const float s = static_cast<float>(sigma);
  for (int y = 0; y < colour.rows; ++y) {
    float* p = colour.ptr<float>(y);
    const int values = colour.cols * 3;
    const std::uint64_t row_key = hash64(frame_key, static_cast<std::uint64_t>(y));
    // Four 16-bit indices from each 64-bit hash of (row, group of four).
    for (int i = 0; i < values; i += 4) {
      std::uint64_t bits = mix64(row_key ^ static_cast<std::uint64_t>(i));
      for (int k = i; k < std::min(i + 4, values); ++k, bits >>= 16) p[k] += s * quantiles[bits & 0xFFFFu];
    }
  }
}

cv::Mat quantise(const cv::Mat& colour) {
  CV_Assert(colour.type() == CV_32FC3);
  cv::Mat out(colour.size(), CV_8UC3);
  for (int y = 0; y < colour.rows; ++y) {
    const float* src = colour.ptr<float>(y);
    std::uint8_t* dst = out.ptr<std::uint8_t>(y);
    for (int i = 0; i < colour.cols * 3; ++i) {
      const float v = std::floor(src[i] + 0.5f);
      dst[i] = static_cast<std::uint8_t>(v < 0.f ? 0.f : v > 255.f ? 255.f : v);
    }
  }
  return out;
}

cv::Mat depth_millimetres(const cv::Mat& depth_m) {
  CV_Assert(depth_m.type() == CV_32FC1);
  cv::Mat out(depth_m.size(), CV_16UC1);
  for (int y = 0; y < depth_m.rows; ++y) {
    const float* src = depth_m.ptr<float>(y);
    std::uint16_t* dst = out.ptr<std::uint16_t>(y);
    for (int x = 0; x < depth_m.cols; ++x) {
      const double mm = std::floor(static_cast<double>(src[x]) * 1000.0 + 0.5);
      dst[x] = (mm >= 1.0 && mm <= 65535.0) ? static_cast<std::uint16_t>(mm) : 0;
    }
  }
  return out;
}

}  // namespace facadeslam::synth
