#include "semantics/evaluation/corner_keypoints.hpp"

#include <algorithm>
#include <string>

#include <opencv2/features2d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"

namespace facadeslam::semantics {

KeypointSource parse_keypoint_source(const std::string& text, const std::string& option) {
  if (text == "grid") return KeypointSource::grid;
  if (text == "corners") return KeypointSource::corners;
  std::string message = option;
  throw Error(message.append(": expected grid or corners, got '").append(text).append("'"));
}

const char* keypoint_source_name(KeypointSource source) { return source == KeypointSource::grid ? "grid" : "corners"; }

std::vector<cv::Point2f> corner_keypoints(const cv::Mat& bgr, int border, int threshold) {
  cv::Mat grey;
  if (bgr.channels() == 3)
    cv::cvtColor(bgr, grey, cv::COLOR_BGR2GRAY);
  else
    grey = bgr;
  std::vector<cv::Point> pixels;
  const auto add_level = [&](const cv::Mat& image, int scale) {
    std::vector<cv::KeyPoint> corners;
    cv::FAST(image, corners, threshold, true);
    for (const cv::KeyPoint& k : corners) {
      const int x = static_cast<int>(k.pt.x) * scale, y = static_cast<int>(k.pt.y) * scale;
      if (x >= border && y >= border && x < bgr.cols - border && y < bgr.rows - border) pixels.emplace_back(x, y);
    }
  };
  add_level(grey, 1);
  cv::Mat half;
  cv::pyrDown(grey, half);
  add_level(half, 2);
  std::sort(pixels.begin(), pixels.end(),
            [](const cv::Point& a, const cv::Point& b) { return a.y != b.y ? a.y < b.y : a.x < b.x; });
  pixels.erase(std::unique(pixels.begin(), pixels.end()), pixels.end());
  std::vector<cv::Point2f> points;
  points.reserve(pixels.size());
  for (const cv::Point& p : pixels) points.emplace_back(static_cast<float>(p.x), static_cast<float>(p.y));
  return points;
}

}  // namespace facadeslam::semantics
