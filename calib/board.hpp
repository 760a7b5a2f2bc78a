#pragma once
// The calibration target: a chessboard described by its number of INNER
// corners (OpenCV's convention: a 10 x 7 squares board is "9x6") and the side
// of one square in metres (any unit works; the focal length does not depend
// on it, only the board poses do).
#include <string>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

namespace facadeslam::calib {

struct BoardSpec {
  int cols = 9;           // inner corners along a row (the board's x axis)
  int rows = 6;           // inner corners along a column (the board's y axis)
  double square = 0.025;  // square side in metres, > 0

  int corner_count() const { return cols * rows; }
  cv::Size pattern_size() const { return {cols, rows}; }
  // "9x6"
  std::string size_text() const;
};

// Parses "WxH" (also "WXH") with integers W, H >= 2. Throws Error naming the
// text and the expected form otherwise.
BoardSpec parse_board_size(const std::string& text, double square);

// Throws Error unless cols, rows >= 2 and square is finite and > 0.
void validate_board(const BoardSpec& board);

// The inner corners in the board frame, row by row as OpenCV reports them:
// corner (i, j) at (i * square, j * square, 0), index j * cols + i.
std::vector<cv::Point3f> board_object_points(const BoardSpec& board);

// The same corner in double precision, for our own residuals and fits.
Eigen::Vector3d board_corner(const BoardSpec& board, int index);

}  // namespace facadeslam::calib
