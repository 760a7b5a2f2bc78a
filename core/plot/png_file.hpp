#pragma once
// Writes a figure as a PNG file atomically (temp file + rename), so that a
// failed or interrupted write never leaves a half-written plot behind.
#include <filesystem>

#include <opencv2/core.hpp>

namespace facadeslam::plot {

// Fails (facadeslam::Error naming the file) when the name does not end in
// .png (any case) or the image cannot be encoded or written.
void save_png(const std::filesystem::path& path, const cv::Mat& image);

}  // namespace facadeslam::plot
