#include "semantics/descriptor/edge_distance.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "semantics/descriptor/kernel_support.hpp"

namespace facadeslam::semantics {
namespace {

constexpr float kFar = 1e15f;  // "no edge in this column yet"

// Distance to the nearest edge pixel in the same column, down then up;
// rows are processed as vectors.
FACADESLAM_KERNEL void column_distances(const cv::Mat& edges, cv::Mat& g) {
  {
    const uchar* e = edges.ptr<uchar>(0);
    float* row = g.ptr<float>(0);
    for (int x = 0; x < edges.cols; ++x) row[x] = e[x] ? 0.0f : kFar;
  }
  for (int y = 1; y < edges.rows; ++y) {
    const uchar* e = edges.ptr<uchar>(y);
    const float* previous = g.ptr<float>(y - 1);
    float* row = g.ptr<float>(y);
    for (int x = 0; x < edges.cols; ++x) row[x] = e[x] ? 0.0f : previous[x] + 1.0f;
  }
  for (int y = edges.rows - 2; y >= 0; --y) {
    const float* next = g.ptr<float>(y + 1);
    float* row = g.ptr<float>(y);
    for (int x = 0; x < edges.cols; ++x) row[x] = row[x] < next[x] + 1.0f ? row[x] : next[x] + 1.0f;
  }
}

// Exact distances along a row from the column distances g:
// d(x)^2 = min over q of (x - q)^2 + g(q)^2. Every value is an integer below
// 2^24, so float arithmetic is exact. Each block of 8 pixels widens its
// search k = 1, 2, ... until k^2 reaches the largest squared distance it has
// found (no farther column can be closer), branch-free across the lanes:
// dense Canny edges keep k small, and the cost follows the distances. Same
// result as a lower envelope of parabolas (Felzenszwalb & Huttenlocher)
// without its data-dependent branches. The stop test (a maximum across the
// lanes, a serial chain) runs every kStepsPerTest steps: a step past the
// bound cannot change a lane (its candidates are >= k^2 >= the lane's best),
// so the result is the same. `squares` holds g^2 with `width` columns of
// kFar^2 on both sides.
FACADESLAM_KERNEL void row_distances(const float* g, int width, float* out, std::vector<float>& squares) {
  squares.assign(static_cast<std::size_t>(3 * width + kLanes), kFar * kFar);
  float* sq = squares.data() + width;
  for (int q = 0; q < width; ++q) sq[q] = g[q] * g[q];
  for (int x = 0; x < width; x += kLanes) {
    FloatLanes best;
    load_lanes(best, sq + x);
    constexpr int kStepsPerTest = 4;
    for (int k = 1; k <= width;) {
      float worst = best[0];
      for (int lane = 1; lane < kLanes; ++lane) worst = best[lane] > worst ? best[lane] : worst;
      if (static_cast<float>(k) * static_cast<float>(k) >= worst) break;
      for (const int end = std::min(width, k + kStepsPerTest - 1); k <= end; ++k) {
        const float reach = static_cast<float>(k) * static_cast<float>(k);
        FloatLanes left, right;
        load_lanes(left, sq + x - k);
        load_lanes(right, sq + x + k);
        const FloatLanes nearer = (left < right ? left : right) + reach;
        best = nearer < best ? nearer : best;
      }
    }
    const int count = x + kLanes <= width ? kLanes : width - x;
    for (int lane = 0; lane < count; ++lane) out[x + lane] = static_cast<float>(std::sqrt(static_cast<double>(best[lane])));
  }
}

}  // namespace

void distance_to_edges(const cv::Mat& edges, cv::Mat& distance) {
  CV_Assert(edges.type() == CV_8U && distance.type() == CV_32F && distance.size() == edges.size());
  if (cv::countNonZero(edges) == 0) {
    distance.setTo(static_cast<float>(std::hypot(edges.cols, edges.rows)));
    return;
  }
  cv::Mat column(edges.size(), CV_32F);
  column_distances(edges, column);
  std::vector<float> squares;
  for (int y = 0; y < edges.rows; ++y) row_distances(column.ptr<float>(y), edges.cols, distance.ptr<float>(y), squares);
}

}  // namespace facadeslam::semantics
