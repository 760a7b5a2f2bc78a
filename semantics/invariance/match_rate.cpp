#include "semantics/invariance/match_rate.hpp"

#include <algorithm>
#include <cmath>

#include "core/util/error.hpp"

namespace facadeslam::semantics {
namespace {

// Rows per block of the distance matrix: 256 x 5000 floats = 5 MB.
constexpr int kBlockRows = 256;

bool counterpart_is_nearest(const float* distances, int count, int own) {
  const float own_distance = distances[own];
  if (!std::isfinite(own_distance)) return false;
  for (int j = 0; j < count; ++j)
    if (j != own && distances[j] <= own_distance) return false;  // false for NaN: ignored
  return true;
}

}  // namespace

std::vector<bool> matched_rows(const cv::Mat& d) {
  if (d.type() != CV_32F || d.rows != d.cols)
    throw Error("match rate: expected a square CV_32F matrix of squared distances");
  std::vector<bool> matched(static_cast<std::size_t>(d.rows));
  for (int i = 0; i < d.rows; ++i)
    matched[static_cast<std::size_t>(i)] = counterpart_is_nearest(d.ptr<float>(i), d.cols, i);
  return matched;
}

std::size_t count_matched(const cv::Mat& reference, const cv::Mat& changed) {
  if (reference.type() != CV_32F || changed.type() != CV_32F || reference.size() != changed.size())
    throw Error("match rate: the two descriptor matrices must be CV_32F and of the same size");
  std::size_t matched = 0;
  cv::Mat distances;
  for (int first = 0; first < reference.rows; first += kBlockRows) {
    const int last = std::min(reference.rows, first + kBlockRows);
    // OpenCV's brute-force kernel (what cv::BFMatcher uses), all pairs.
    cv::batchDistance(reference.rowRange(first, last), changed, distances, CV_32F, cv::noArray(), cv::NORM_L2SQR);
    for (int i = first; i < last; ++i)
      if (counterpart_is_nearest(distances.ptr<float>(i - first), changed.rows, i)) ++matched;
  }
  return matched;
}

double match_rate(std::size_t matched, std::size_t rows) {
  return rows ? static_cast<double>(matched) / static_cast<double>(rows) : std::nan("");
}

}  // namespace facadeslam::semantics
