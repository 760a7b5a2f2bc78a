#include "semantics/point_descriptors/keypoint_rows.hpp"

#include "core/util/error.hpp"

namespace facadeslam::semantics {

std::vector<cv::KeyPoint> upright_keypoints(const std::vector<cv::Point2f>& points, float size, cv::Point2f offset) {
  std::vector<cv::KeyPoint> keypoints;
  keypoints.reserve(points.size());
  for (std::size_t i = 0; i < points.size(); ++i)
    keypoints.emplace_back(points[i] + offset, size, 0.0f, 0.0f, 0, static_cast<int>(i));
  return keypoints;
}

cv::Mat rows_by_index(const std::vector<cv::KeyPoint>& survivors, const cv::Mat& computed, std::size_t count,
                      int width) {
  cv::Mat rows = cv::Mat::zeros(static_cast<int>(count), width, CV_32F);
  if (survivors.empty()) return rows;
  if (computed.rows != static_cast<int>(survivors.size()) || computed.cols != width)
    throw Error("descriptor: OpenCV returned a descriptor matrix that does not match its keypoints");
  cv::Mat as_float;
  computed.convertTo(as_float, CV_32F);
  for (std::size_t s = 0; s < survivors.size(); ++s) {
    const int k = survivors[s].class_id;
    if (k < 0 || static_cast<std::size_t>(k) >= count) throw Error("descriptor: OpenCV changed a keypoint's id");
    as_float.row(static_cast<int>(s)).copyTo(rows.row(k));
  }
  return rows;
}

}  // namespace facadeslam::semantics
