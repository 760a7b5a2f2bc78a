#include "calib/view_quality.hpp"

#include <algorithm>
#include <limits>

#include <opencv2/calib3d.hpp>

#include "core/util/error.hpp"

namespace facadeslam::calib {

double board_edge_width(const cv::Mat& gray, const BoardSpec& board, const std::vector<cv::Point2f>& corners) {
  // OpenCV throws on boards it cannot walk (e.g. a corner row touching the
  // border); no measurement is then reported rather than a rejection.
  try {
    const cv::Scalar sharpness = cv::estimateChessboardSharpness(gray, board.pattern_size(), corners);
    return sharpness[0] > 0.0 ? sharpness[0] : std::numeric_limits<double>::quiet_NaN();
  } catch (const cv::Exception&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

double mean_corner_distance(const std::vector<cv::Point2f>& a, const std::vector<cv::Point2f>& b) {
  if (a.size() != b.size() || a.empty()) throw Error("mean_corner_distance: expected two equally long corner lists");
  const std::size_t n = a.size();
  double straight = 0.0, reversed = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    straight += cv::norm(a[i] - b[i]);
    reversed += cv::norm(a[i] - b[n - 1 - i]);
  }
  return std::min(straight, reversed) / static_cast<double>(n);
}

}  // namespace facadeslam::calib
