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

// Per-row buffers of row_distances.
struct RowScratch {
  std::vector<float> squares;   // g^2, with `width` columns of kFar^2 on both sides
  std::vector<float> best;      // the best squared distance found so far, per pixel
  std::vector<int> unfinished;  // first pixels of the blocks pass 1 left unfinished
};

// Steps k = first..last of a block's outward search (see row_distances).
[[gnu::always_inline]] inline void search_steps(const float* sq, int x, int first, int last, FloatLanes& best) {
  for (int k = first; k <= last; ++k) {
    const float reach = static_cast<float>(k) * static_cast<float>(k);
    FloatLanes left, right;
    load_lanes(left, sq + x - k);
    load_lanes(right, sq + x + k);
    const FloatLanes nearer = (left < right ? left : right) + reach;
    best = nearer < best ? nearer : best;
  }
}

[[gnu::always_inline]] inline float lane_max(const FloatLanes& v) {
  float worst = v[0];
  for (int lane = 1; lane < kLanes; ++lane) worst = v[lane] > worst ? v[lane] : worst;
  return worst;
}

// Exact distances along a row from the column distances g:
// d(x)^2 = min over q of (x - q)^2 + g(q)^2. Every value is an integer below
// 2^24 (images with a diagonal under ~2900 pixels), so float arithmetic is
// exact. Each block of 8 pixels widens its search k = 1, 2, ... until k^2
// reaches the largest squared distance it has found (no farther column can
// be closer): dense Canny edges keep k small, and the cost follows the
// distances. Same result as a lower envelope of parabolas (Felzenszwalb &
// Huttenlocher) without its data-dependent branches. A step past the bound
// cannot change a lane (its candidates are >= k^2 >= the lane's best), so
// steps may be taken past it:
//  - pass 1 takes the first kFirstSteps steps of every block unconditionally
//    and lists the blocks whose bound lies beyond (no branch per block: the
//    stop test's outcome varies from block to block and mispredicted);
//  - pass 2 continues the listed blocks, testing the bound (a maximum across
//    the lanes, a serial chain) every kStepsPerTest steps;
//  - pass 3 takes the square roots.
FACADESLAM_KERNEL void row_distances(const float* g, int width, float* out, RowScratch& scratch) {
  const int blocks = (width + kLanes - 1) / kLanes;
  scratch.squares.assign(static_cast<std::size_t>(3 * width + kLanes), kFar * kFar);
  scratch.best.resize(static_cast<std::size_t>(blocks * kLanes));
  scratch.unfinished.resize(static_cast<std::size_t>(blocks));
  float* sq = scratch.squares.data() + width;
  float* best_of = scratch.best.data();
  int* unfinished = scratch.unfinished.data();
  for (int q = 0; q < width; ++q) sq[q] = g[q] * g[q];

  constexpr int kFirstSteps = 4, kStepsPerTest = 4;
  const int first_steps = std::min(width, kFirstSteps);
  const float first_bound = static_cast<float>(first_steps + 1) * static_cast<float>(first_steps + 1);
  int unfinished_count = 0;
  for (int x = 0; x < width; x += kLanes) {
    FloatLanes best;
    load_lanes(best, sq + x);
    search_steps(sq, x, 1, first_steps, best);
    store_lanes(best_of + x, best);
    unfinished[unfinished_count] = x;
    unfinished_count += first_steps < width && first_bound < lane_max(best);
  }
  for (int i = 0; i < unfinished_count; ++i) {
    const int x = unfinished[i];
    FloatLanes best;
    load_lanes(best, best_of + x);
    for (int k = first_steps + 1; k <= width;) {
      if (static_cast<float>(k) * static_cast<float>(k) >= lane_max(best)) break;
      const int end = std::min(width, k + kStepsPerTest - 1);
      search_steps(sq, x, k, end, best);
      k = end + 1;
    }
    store_lanes(best_of + x, best);
  }
  // A float square root of these exact integers is the float of the double
  // one (double rounding is innocuous for sqrt: 53 >= 2 * 24 + 2 bits).
  for (int x = 0; x < width; ++x) out[x] = std::sqrt(best_of[x]);
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
  RowScratch scratch;
  for (int y = 0; y < edges.rows; ++y) row_distances(column.ptr<float>(y), edges.cols, distance.ptr<float>(y), scratch);
}

}  // namespace facadeslam::semantics
