#pragma once
// The photometric invariance cases (thesis III.4.3 and IV.5): the geometry
// stays, the pixel values change. All take and return 8-bit BGR images;
// results are rounded and saturated to 0..255 as a camera would store them.
#include <opencv2/core.hpp>

namespace facadeslam::semantics {

// Gaussian blur with a kernel x kernel window (odd, >= 1; 1 = unchanged) and
// OpenCV's sigma for that size, 0.3 ((kernel - 1) / 2 - 1) + 0.8.
cv::Mat blur_image(const cv::Mat& bgr, int kernel);
// Light intensity change, eq. III.37: every channel times `factor` (> 0).
cv::Mat scale_intensity(const cv::Mat& bgr, double factor);
// Light intensity shift, eq. III.38: `offset` added to every channel.
cv::Mat shift_intensity(const cv::Mat& bgr, double offset);
// Light colour change, eq. III.39, with the gains of illuminant.hpp.
cv::Mat change_illuminant(const cv::Mat& bgr, double kelvin);
// Encoded and decoded as JPEG at `quality` (0..100).
cv::Mat jpeg_round_trip(const cv::Mat& bgr, int quality);

}  // namespace facadeslam::semantics
