#include "semantics/evaluation/grid_keypoints.hpp"

#include "core/util/error.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {

std::vector<cv::Point2f> grid_keypoints(cv::Size image_size, int step, int border) {
  if (step < 1) throw Error(cat("keypoint grid: the step must be at least 1 pixel, got ", step));
  if (border < 0) throw Error(cat("keypoint grid: the border must be >= 0, got ", border));
  std::vector<cv::Point2f> points;
  for (int y = border; y < image_size.height - border; y += step)
    for (int x = border; x < image_size.width - border; x += step)
      points.emplace_back(static_cast<float>(x), static_cast<float>(y));
  return points;
}

}  // namespace facadeslam::semantics
