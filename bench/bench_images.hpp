#pragma once
// Test images for the benchmarks: a real facade photo when ../shared/data is
// present (resized to the requested size), else a deterministic synthetic
// texture, so the benchmarks always run.
#include <string>

#include <opencv2/core.hpp>

namespace facadeslam::bench {

// BGR image of `size`; `source` tells which image was used.
cv::Mat facade_image(cv::Size size, std::string* source = nullptr);

}  // namespace facadeslam::bench
