#pragma once
// The geometric invariance cases: rotation, resize and ten affine cases.
// Each returns the warped image with the exact map of pixel positions
// (pixel (0,0) = centre of the top-left pixel) and the mask of pixels that
// show the original.
//
// Rotation and the affine cases act about the image centre and keep the
// whole warped image: the canvas is the bounding box of the warped image
// area, the rest filled with black (marked invalid). Resize scales the image
// to round(factor x size) with cv::resize (area averaging when shrinking, so
// that a smaller image is what a camera further away would see, not an
// aliased one).
//
// The ten affine cases: any affine map is a zoom, two rotations and a tilt
// (Morel and Yu's ASIFT decomposition). Zoom and rotation have their own
// cases, so the affine cases vary the rest: the tilt, i.e. the foreshortening
// of a plane seen from a viewpoint angle theta, which compresses the image by
// cos(theta) along one direction phi:
//     A = I - (1 - cos theta) u u^T,  u = (cos phi, sin phi).
//   cases 1-5:  phi = 0   (walking past a facade), theta = 20, 30, 40, 50, 60 deg
//   cases 6-10: phi = 45  (an oblique view: shear and anisotropic scale),
//               theta = 20, 30, 40, 50, 60 deg
//   case 0:     the identity (the reference point of the curve).
#include <string>

#include <opencv2/core.hpp>

#include "semantics/invariance/transformed_image.hpp"

namespace facadeslam::semantics {

inline constexpr int kAffineCaseCount = 10;

// The 2x2 linear part of affine case 0..kAffineCaseCount (Error otherwise).
cv::Matx22d affine_case_matrix(int affine_case);
// "tilt 40 deg along 0 deg" (for reports).
std::string affine_case_description(int affine_case);

// Warps `bgr` (CV_8UC3) by the linear map `linear` about its centre onto the
// bounding box of the result (bilinear interpolation, black fill).
TransformedImage warp_about_centre(const cv::Mat& bgr, const cv::Matx22d& linear);

// Counter-clockwise on screen (OpenCV's getRotationMatrix2D sense).
TransformedImage rotate_image(const cv::Mat& bgr, double degrees);
// factor > 0; the result is at least 1 x 1 pixels.
TransformedImage resize_image(const cv::Mat& bgr, double factor);
TransformedImage affine_image(const cv::Mat& bgr, int affine_case);

}  // namespace facadeslam::semantics
