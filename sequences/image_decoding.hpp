#pragma once
// Turns whatever an image file holds into the 8-bit BGR the tracker expects.
#include <filesystem>
#include <optional>

#include <opencv2/core.hpp>

namespace facadeslam {

// Decodes one image file. Nothing when the file cannot be decoded (missing,
// truncated, not an image): the caller decides whether that stops the
// sequence. A decodable image in a layout we cannot convert is an Error.
std::optional<cv::Mat> read_image_bgr8(const std::filesystem::path& path);

// Converts a decoded image to CV_8UC3 BGR:
//  - grey is replicated into three channels, BGRA drops alpha;
//  - 16-bit is scaled by 255/65535 (the full 16-bit range onto 0..255). A
//    fixed scale, not a per-image stretch, so the brightness of a scene does
//    not jump from frame to frame — the tracker compares intensities;
//  - float is taken as 0..1 and scaled by 255 (saturating).
// Other depths or channel counts throw Error naming `origin`.
cv::Mat to_bgr8(const cv::Mat& decoded, const std::filesystem::path& origin);

}  // namespace facadeslam
