#pragma once
// Maximum-likelihood-style polishing of a homography. cv::findHomography
// refines on the one-sided transfer error |x1 - H x0|, as if the first
// image's pixels were exact; both are equally noisy KLT positions, so the
// symmetric transfer error (both directions) is minimised here instead. For
// a facade the pose comes from decomposing H, and its translation direction
// is the sensitive part: a rotation error dw shows up as a direction error of
// about dw * d / |t| (the planar bas-relief coupling), so every bit of H
// accuracy counts.
#include <vector>

#include <Eigen/Core>

namespace facadeslam {

// Refines H (x1 ~ H x0) on the matches `indices` with Levenberg-Marquardt on
// the Huber-weighted symmetric transfer errors (pixels). H moves on the unit
// sphere of 3x3 matrices (8 degrees of freedom); the result has Frobenius
// norm 1 (the input, so normalised, when nothing improves).
Eigen::Matrix3d refine_homography(const Eigen::Matrix3d& H, const std::vector<Eigen::Vector2d>& x0,
                                  const std::vector<Eigen::Vector2d>& x1, const std::vector<int>& indices,
                                  double huber_px, int max_iterations = 20);

}  // namespace facadeslam
