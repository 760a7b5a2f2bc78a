#pragma once
// Writes a picture as a PNG file atomically (temp file + rename), so that a
// failed or interrupted write never leaves a half-written one behind, and
// signed as this program's (core/util/png_signature.hpp): every PNG the
// program writes goes through here.
#include <filesystem>
#include <vector>

#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>

namespace facadeslam::plot {

// Fails (facadeslam::Error naming the file) when the name does not end in
// .png (any case) or the image cannot be encoded or written.
// `parameters` are cv::imencode's: by default zlib's level 9, for plots
// committed under docs/ (it costs milliseconds on pictures of this size).
void save_png(const std::filesystem::path& path, const cv::Mat& image,
              const std::vector<int>& parameters = {cv::IMWRITE_PNG_COMPRESSION, 9});

}  // namespace facadeslam::plot
