#pragma once
// What a two-view initialisation attempt returns.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/lie/se3.hpp"

namespace facadeslam {

enum class InitStatus {
  need_more_parallax,  // the camera has not moved enough yet: keep feeding frames
  too_few_tracks,      // the tracks died: restart from a new reference frame (reset)
  degenerate,          // moved, but the geometry cannot be trusted yet (pure rotation,
                       // too little parallax angle, ambiguous, too few good points):
                       // keep feeding frames, the reference is kept
  success,
};

enum class TwoViewModel { homography, essential };

const char* to_string(InitStatus status);
const char* to_string(TwoViewModel model);

struct TwoViewResult {
  InitStatus status = InitStatus::need_more_parallax;
  // Why the attempt did not succeed, one line for the log (empty on success).
  std::string reason;

  // Filled on success: the second camera from the first (maps points from
  // the first camera frame to the second) and the triangulated points in the
  // first camera frame. Scale: the median depth (z) of points_c0 is 1;
  // |t| of T_c1_c0 is in the same unit.
  SE3d T_c1_c0;
  std::vector<Eigen::Vector3d> points_c0;
  // Per point: its level-0 pixels in both frames (as given) and the index of
  // that pixel pair in the input matches.
  std::vector<Eigen::Vector2d> pixels0;
  std::vector<Eigen::Vector2d> pixels1;
  std::vector<int> match_indices;

  // Filled as far as the attempt got (diagnostics on failure too). Scores
  // and inlier counts are those of the two RANSAC models that were compared
  // (model_scoring.hpp), before either is refined.
  int matches = 0;
  double median_image_motion_px = 0.0;
  TwoViewModel model = TwoViewModel::essential;
  double score_homography = 0.0;
  double score_essential = 0.0;
  double homography_ratio = 0.0;  // R_H = S_H / (S_H + S_E)
  int inliers_homography = 0;
  int inliers_essential = 0;
  double median_parallax_deg = 0.0;  // over the points in front of both cameras
};

}  // namespace facadeslam
