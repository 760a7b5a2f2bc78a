#pragma once
// Glue between the PointDescriptor contract (one row per keypoint, in
// order) and OpenCV's Feature2D::compute, which may drop or reorder the
// keypoints it is given.
#include <vector>

#include <opencv2/core.hpp>

namespace facadeslam::semantics {

// Upright keypoints (angle 0: grid keypoints have no orientation) of the
// given size, moved by `offset` (for padded images), with class_id = index
// so that rows can be traced back after compute().
std::vector<cv::KeyPoint> upright_keypoints(const std::vector<cv::Point2f>& points, float size,
                                            cv::Point2f offset = {0.0f, 0.0f});

// A count x width CV_32F matrix: row k = the computed row of the keypoint
// whose class_id is k, converted to float; keypoints compute() dropped keep
// a row of zeros. `computed` has one row per survivor.
cv::Mat rows_by_index(const std::vector<cv::KeyPoint>& survivors, const cv::Mat& computed, std::size_t count,
                      int width);

}  // namespace facadeslam::semantics
