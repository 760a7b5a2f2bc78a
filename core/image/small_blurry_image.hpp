#pragma once
// PTAM's "small blurry image" (SBI): the frame shrunk to 40x30 (for a
// 640x480 camera), heavily blurred and made zero-mean. Every keyframe keeps
// one; after a tracking failure the current frame's SBI is compared with all
// of them (relocaliser.hpp). Blurring makes the comparison tolerant of the
// few pixels of shift and rotation that separate a lost frame from the
// keyframe it is near, and zero-mean makes it tolerant of exposure changes.
#include <opencv2/core.hpp>

#include "core/image/image_pyramid.hpp"

namespace facadeslam {

struct SmallBlurryImageOptions {
  // The SBI is the top pyramid level half-sampled once more: 1/16 of the
  // frame on each side (40x30 at 640x480).
  double blur_sigma = 2.5;  // Gaussian blur in SBI pixels (PTAM's value)
};

// CV_32FC1, zero-mean. The scale from level-0 pixels to SBI pixels is
// sbi_scale() on each axis (pixel-centre convention as in the pyramid).
cv::Mat make_small_blurry_image(const ImagePyramid& pyramid, const SmallBlurryImageOptions& options = {});
inline constexpr int kSbiLevel = kPyramidLevels;  // one half-sampling past the top level

// Sum of squared differences of two zero-mean SBIs of the same size.
double sbi_difference(const cv::Mat& a, const cv::Mat& b);

// In-image motion between two SBIs: current(x) ~ reference(R(theta) (x - c) + c + t),
// with c the image centre, found by Gauss-Newton on the image gradients.
struct Se2Motion {
  double theta = 0;         // radians
  Eigen::Vector2d t{0, 0};  // SBI pixels
  double residual_rms = 0;  // after alignment, in SBI grey levels
};
Se2Motion align_small_blurry_images(const cv::Mat& reference, const cv::Mat& current, int iterations = 30);

}  // namespace facadeslam
