#pragma once
// Test images for the benchmarks: a real facade photo when ../shared/data is
// present (resized to the requested size), else a deterministic synthetic
// texture, so the benchmarks always run.
#include <string>
#include <vector>

#include <opencv2/core.hpp>

namespace facadeslam::bench {

// BGR image of `size`; `source` tells which image was used.
cv::Mat facade_image(cv::Size size, std::string* source = nullptr);

// The thesis' grid keypoints over an image of `size`: every `step` pixels
// from the corner (the descriptor benches' workload).
std::vector<cv::Point2f> grid_points(cv::Size size, int step = 9);

}  // namespace facadeslam::bench
