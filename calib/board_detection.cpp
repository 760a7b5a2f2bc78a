#include "calib/board_detection.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"

namespace facadeslam::calib {

int subpixel_half_window(const std::vector<cv::Point2f>& corners, const BoardSpec& board) {
  double min_spacing = std::numeric_limits<double>::infinity();
  for (int j = 0; j < board.rows; ++j)
    for (int i = 0; i < board.cols; ++i) {
      const cv::Point2f& c = corners[j * board.cols + i];
      if (i + 1 < board.cols)
        min_spacing = std::min(min_spacing, double(cv::norm(c - corners[j * board.cols + i + 1])));
      if (j + 1 < board.rows)
        min_spacing = std::min(min_spacing, double(cv::norm(c - corners[(j + 1) * board.cols + i])));
    }
  return std::clamp(static_cast<int>(std::floor(0.35 * min_spacing)), 3, 11);
}

std::optional<BoardDetection> detect_board(const cv::Mat& gray, const BoardSpec& board) {
  if (gray.empty() || gray.type() != CV_8UC1) throw Error("detect_board: expected a non-empty 8-bit grey image");
  BoardDetection detection;
  const int classic_flags = cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_FAST_CHECK;
  bool found = cv::findChessboardCorners(gray, board.pattern_size(), detection.corners, classic_flags);
  if (!found) {
    // Without CALIB_CB_EXHAUSTIVE / CALIB_CB_ACCURACY, which make a miss
    // cost seconds; the corners are refined below like the classic ones.
    detection.corners.clear();
    found = cv::findChessboardCornersSB(gray, board.pattern_size(), detection.corners, cv::CALIB_CB_NORMALIZE_IMAGE) &&
            static_cast<int>(detection.corners.size()) == board.corner_count();
    detection.sector_based = found;
  }
  if (!found) return std::nullopt;
  const int half = subpixel_half_window(detection.corners, board);
  cv::cornerSubPix(gray, detection.corners, cv::Size(half, half), cv::Size(-1, -1),
                   cv::TermCriteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 40, 1e-4));
  return detection;
}

}  // namespace facadeslam::calib
