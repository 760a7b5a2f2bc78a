#pragma once
// Ground truth from LabelMeFacade's colour label images: each pixel's colour
// is one of the nine class colours (core/map/semantic_classes.hpp).
// cv::imread(IMREAD_COLOR) turns the 16-bit RGBA PNGs into 8-bit BGR with
// channel values 0 / 64 / 128.
#include <cstdint>
#include <filesystem>
#include <vector>

#include <opencv2/core.hpp>

namespace facadeslam::semantics {

inline constexpr std::uint8_t kUnknownClass = 255;

// The class id of a BGR label colour, or kUnknownClass for any other colour.
std::uint8_t class_of_colour(const cv::Vec3b& bgr);

// Reads a label image as 8-bit BGR. Throws Error naming the file when it is
// missing or not an image.
cv::Mat read_label_image(const std::filesystem::path& path);

// The class id at each keypoint (nearest pixel); kUnknownClass where the
// colour is no class colour. Keypoints must lie inside the image.
std::vector<std::uint8_t> classes_at(const cv::Mat& label_bgr, const std::vector<cv::Point2f>& keypoints);

}  // namespace facadeslam::semantics
