#pragma once
// Settings of the automatic two-view initialisation. Every figure is chosen
// for a 640x480 webcam tracked with KLT (match noise well under 1 px) and
// scales with the image where that matters; the comments say why.
namespace facadeslam {

// Frame-to-frame KLT tracking of the reference frame's corners.
struct CornerTrackOptions {
  // Corners kept from the reference frame. When the pyramid offers more, the
  // strongest are taken cell by cell (round robin over a grid of
  // spread_cell_px cells) so that they stay spread over the whole image: a
  // well-spread set is what makes the homography/essential choice reliable.
  int max_corners = 1000;
  int spread_cell_px = 40;
  // cv::calcOpticalFlowPyrLK window (pixels, odd) and top pyramid level
  // (3 = four levels, enough for ~40 px of frame-to-frame motion).
  int window_size = 21;
  int max_level = 3;
  int max_iterations = 30;
  double epsilon = 0.01;
  // A track dies when tracking it back from the new frame lands more than
  // this far from where it started (occlusion, drift on an edge), or when it
  // comes closer than border_px to the image edge.
  double max_forward_backward_px = 1.0;
  double border_px = 2.0;
};

struct TwoViewOptions {
  CornerTrackOptions tracking;

  // Fewer surviving tracks (or matches) than this: restart from a new
  // reference frame (status too_few_tracks).
  int min_tracks = 100;

  // No model is tried until the median image motion of the tracks reaches
  // this fraction of the image diagonal (1.5% = 12 px at 640x480): below it
  // there cannot be enough parallax and RANSAC would only waste time.
  double min_image_motion_fraction = 0.015;

  // Standard deviation of the match noise in pixels. The RANSAC thresholds
  // and the chi-square cut-offs of the model scores derive from it:
  // homography transfer error (2 dof) < 5.991 sigma^2 per direction,
  // epipolar distance (1 dof) < 3.841 sigma^2 per direction (95%).
  double match_sigma_px = 1.0;
  // RANSAC stops at this confidence; 500 iterations cover 50% outliers for
  // the five-point essential matrix (218 needed at 0.999) and bound the time
  // of a hopeless attempt (every match wrong), which runs all of them.
  double ransac_confidence = 0.999;
  int ransac_max_iterations = 500;

  // R_H = S_H / (S_H + S_E) above this picks the homography (ORB-SLAM's 0.45):
  // when both models explain the matches equally well R_H is about 0.5, and
  // the homography, the simpler and better conditioned model, is preferred;
  // a general 3D scene drives R_H far lower.
  double homography_ratio_threshold = 0.45;

  // A triangulated point is kept only with at least this angle between its
  // two viewing rays: below it depth is too uncertain to seed the map.
  double min_point_parallax_deg = 1.0;
  // The whole reconstruction needs at least this median parallax angle over
  // the points in front of both cameras; below it is "degenerate" (too little
  // translation for the depth, or pure rotation).
  double min_median_parallax_deg = 1.0;
  // Reprojection error allowed in both images, in real (distorted) pixels.
  double max_reprojection_error_px = 2.0;
  // Minimum number of good points, and minimum share of the chosen model's
  // inliers that must triangulate well.
  int min_points = 50;
  double min_triangulated_fraction = 0.5;
  // Two pose hypotheses are ambiguous when the runner-up triangulates more
  // than this share of the winner's good points (the two-fold homography
  // ambiguity, or an essential matrix from nearly planar points).
  double ambiguity_ratio = 0.75;
  // Pure rotation: the homography explains the matches and its
  // translation-over-plane-distance |t|/d (the spread of its singular
  // values) is below this. 0.01 means under ~0.6 degrees of parallax.
  double pure_rotation_max_translation = 0.01;
};

// Throws Error naming the first option out of range.
void validate(const CornerTrackOptions& options);
void validate(const TwoViewOptions& options);

}  // namespace facadeslam
