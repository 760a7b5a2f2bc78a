#pragma once
// Checks that keep unusable views out of the calibration.
//
// Blur: cv::estimateChessboardSharpness walks from black to white square
// centres and measures how many pixels the 10 %..90 % intensity rise takes.
// A sharp image needs about 1-3 px; OpenCV's own sample boards measure
// 2.5-3.5 px. Beyond ~5 px (a Gaussian blur of sigma ~2 px, or motion blur)
// corner positions become biased along the blur direction, so such views do
// more harm than good.
//
// Duplicates: two views whose corners lie (nearly) on top of each other add
// no constraint on the intrinsics but double the weight of that one pose,
// pulling the solution towards it; we keep the first.
#include <vector>

#include <opencv2/core.hpp>

#include "calib/board.hpp"

namespace facadeslam::calib {

struct QualityThresholds {
  // Largest accepted black-to-white edge width, pixels.
  double max_edge_width_px = 5.0;
  // Views whose mean corner distance to an accepted view is below this
  // fraction of the image diagonal are duplicates.
  double duplicate_fraction = 0.01;
};

// Mean 10 %..90 % edge rise width over the board, in pixels; NaN when
// OpenCV cannot measure it (the view is then not judged on blur).
double board_edge_width(const cv::Mat& gray, const BoardSpec& board, const std::vector<cv::Point2f>& corners);

// Mean distance between corresponding corners of two detections of the same
// board, in pixels. Detectors may number the corners of a view from either
// end (a 180-degree turn of the board looks alike), so the smaller of the
// straight and reversed correspondence is taken.
double mean_corner_distance(const std::vector<cv::Point2f>& a, const std::vector<cv::Point2f>& b);

}  // namespace facadeslam::calib
