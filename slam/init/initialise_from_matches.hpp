#pragma once
// The geometric core of the automatic initialisation: from pixel matches
// between a reference frame and the current frame, decide whether the two
// views can seed the map, and if so return the relative pose and the
// triangulated points.
//
// Pipeline (all figures in TwoViewOptions):
//  1. too few matches -> too_few_tracks; median image motion under the gate
//     -> need_more_parallax (nothing is estimated).
//  2. Matches become "ideal" pixels (Camera::unproject, then the pinhole
//     K of the same camera), so distortion and the ATAN model are handled
//     and RANSAC thresholds stay in pixels.
//  3. A homography (cv::findHomography, RANSAC + refinement, then polished
//     on the symmetric transfer error) and an essential matrix
//     (cv::findEssentialMat, five-point RANSAC) are estimated on the same
//     matches and scored ORB-SLAM style (model_scoring.hpp). A homography
//     that is a rotation (|t|/d tiny) while it explains the matches as well
//     as the essential matrix means pure rotation -> degenerate.
//  4. R_H = S_H / (S_H + S_E) > 0.45 picks the homography, else the
//     essential matrix. Its pose hypotheses (cv::decomposeHomographyMat: up
//     to 4; cv::decomposeEssentialMat: 4) are triangulated on the model's
//     inliers; the one with the most good points wins (ties: lower
//     reprojection error). Too little median parallax, too few good points,
//     or a runner-up with more than ambiguity_ratio of the winner's good
//     points -> degenerate.
//  5. For the essential matrix, the winner's rotation and translation
//     direction are refined on the Sampson distances of its consistent
//     inliers (RANSAC gives a minimal-sample estimate). A homography's pose
//     is kept as decomposed from the polished H (see the .cpp for why).
//  6. Every match (not only the model's inliers: points off a dominant
//     plane are kept when they fit the pose) is triangulated under the final
//     pose. Too little median parallax, fewer than min_points good points, or
//     less than min_triangulated_fraction of the inliers good -> degenerate;
//     otherwise the good points are the result, scaled so that their median
//     depth in camera 0 is 1.
//
// Deterministic: the same input gives bit-identical output (OpenCV's RANSAC
// seeds its generator with a constant), as the map maker's --sync mode needs.
#include <vector>

#include <Eigen/Core>

#include "core/camera/camera.hpp"
#include "slam/init/init_options.hpp"
#include "slam/init/two_view_result.hpp"

namespace facadeslam {

// pixels0[i] (reference frame) and pixels1[i] (current frame) are the level-0
// pixels of match i. Throws Error when the lists differ in length, a pixel is
// not finite, or an option is out of range; every other outcome is a status
// in the result.
TwoViewResult initialise_from_matches(const Camera& camera, const std::vector<Eigen::Vector2d>& pixels0,
                                      const std::vector<Eigen::Vector2d>& pixels1, const TwoViewOptions& options);

}  // namespace facadeslam
