#include "calib/board.hpp"

#include <charconv>
#include <cmath>

#include "core/util/error.hpp"

namespace facadeslam::calib {
namespace {

bool parse_int(const std::string& text, int& value) {
  if (text.empty()) return false;
  const char* end = text.data() + text.size();
  const auto [ptr, ec] = std::from_chars(text.data(), end, value);
  return ec == std::errc() && ptr == end;
}

}  // namespace

std::string BoardSpec::size_text() const { return std::to_string(cols) + "x" + std::to_string(rows); }

BoardSpec parse_board_size(const std::string& text, double square) {
  const auto fail = [&] {
    throw Error("board size '" + text +
                "': expected WxH, the number of inner corners per row and per column, both integers >= 2 "
                "(e.g. 9x6 for a board of 10 x 7 squares)");
  };
  const auto x = text.find_first_of("xX");
  if (x == std::string::npos) fail();
  BoardSpec board;
  if (!parse_int(text.substr(0, x), board.cols) || !parse_int(text.substr(x + 1), board.rows)) fail();
  if (board.cols < 2 || board.rows < 2) fail();
  board.square = square;
  validate_board(board);
  return board;
}

void validate_board(const BoardSpec& board) {
  if (board.cols < 2 || board.rows < 2)
    throw Error("board " + board.size_text() + ": expected at least 2 x 2 inner corners");
  if (!std::isfinite(board.square) || board.square <= 0.0)
    throw Error("board square size " + std::to_string(board.square) + ": expected a length > 0 (metres)");
}

std::vector<cv::Point3f> board_object_points(const BoardSpec& board) {
  std::vector<cv::Point3f> points;
  points.reserve(board.corner_count());
  for (int j = 0; j < board.rows; ++j)
    for (int i = 0; i < board.cols; ++i)
      points.emplace_back(static_cast<float>(i * board.square), static_cast<float>(j * board.square), 0.0f);
  return points;
}

Eigen::Vector3d board_corner(const BoardSpec& board, int index) {
  return {(index % board.cols) * board.square, (index / board.cols) * board.square, 0.0};
}

}  // namespace facadeslam::calib
