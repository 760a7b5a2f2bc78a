#include "core/image/image_pyramid.hpp"

#include <opencv2/imgproc.hpp>

#include "core/image/half_sample.hpp"
#include "core/util/error.hpp"

namespace facadeslam {

cv::Mat to_grey(const cv::Mat& image) {
  if (image.type() == CV_8UC1) return image;
  if (image.type() == CV_8UC3) {
    cv::Mat grey;
    cv::cvtColor(image, grey, cv::COLOR_BGR2GRAY);
    return grey;
  }
  throw Error("to_grey: expected an 8-bit grey or BGR image");
}

ImagePyramid::ImagePyramid(const cv::Mat& image, const PyramidOptions& options) {
  constexpr int kMinSide = 8 << (kPyramidLevels - 1);
  if (image.cols < kMinSide || image.rows < kMinSide)
    throw Error("image pyramid: image is " + std::to_string(image.cols) + "x" + std::to_string(image.rows) +
                ", expected at least " + std::to_string(kMinSide) + " pixels on each side");
  levels_[0].image = to_grey(image);
  for (int l = 1; l < kPyramidLevels; ++l)
    levels_[static_cast<std::size_t>(l)].image = half_sample(levels_[static_cast<std::size_t>(l - 1)].image);
  if (options.detect_corners)
    for (int l = 0; l < kPyramidLevels; ++l) {
      auto& level = levels_[static_cast<std::size_t>(l)];
      level.corners = detect_fast(level.image, options.fast[static_cast<std::size_t>(l)]);
    }
}

Eigen::Vector2d ImagePyramid::level0_to_level(const Eigen::Vector2d& x0, int level) {
  const double s = level_scale(level);
  return (x0.array() + 0.5) / s - 0.5;
}

Eigen::Vector2d ImagePyramid::level_to_level0(const Eigen::Vector2d& xl, int level) {
  const double s = level_scale(level);
  return (xl.array() + 0.5) * s - 0.5;
}

}  // namespace facadeslam
