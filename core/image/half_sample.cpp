#include "core/image/half_sample.hpp"

#include "core/util/error.hpp"

namespace facadeslam {

cv::Mat half_sample(const cv::Mat& grey) {
  if (grey.type() != CV_8UC1) throw Error("half_sample: expected an 8-bit single-channel image");
  cv::Mat out(grey.rows / 2, grey.cols / 2, CV_8UC1);
  for (int y = 0; y < out.rows; ++y) {
    const std::uint8_t* top = grey.ptr<std::uint8_t>(2 * y);
    const std::uint8_t* bottom = grey.ptr<std::uint8_t>(2 * y + 1);
    std::uint8_t* dst = out.ptr<std::uint8_t>(y);
    for (int x = 0; x < out.cols; ++x) {
      const int sum = top[2 * x] + top[2 * x + 1] + bottom[2 * x] + bottom[2 * x + 1];
      dst[x] = static_cast<std::uint8_t>((sum + 2) >> 2);
    }
  }
  return out;
}

}  // namespace facadeslam
