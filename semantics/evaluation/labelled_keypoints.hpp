#pragma once
// The labelled grid keypoints of one image: the grid (grid_keypoints.hpp)
// minus the points whose label colour is no class colour, which are only
// counted. Training and testing see the same keypoints this way.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <opencv2/core.hpp>

namespace facadeslam::semantics {

struct LabelledKeypoints {
  std::vector<cv::Point2f> points;
  std::vector<std::uint8_t> classes;  // class id per point
  std::size_t unlabelled = 0;         // grid points dropped (unknown colour)
};

LabelledKeypoints labelled_keypoints(const cv::Mat& label_bgr, int step);

// The same for given points (corner_keypoints.hpp, say).
LabelledKeypoints labelled_keypoints(const cv::Mat& label_bgr, const std::vector<cv::Point2f>& points);

}  // namespace facadeslam::semantics
