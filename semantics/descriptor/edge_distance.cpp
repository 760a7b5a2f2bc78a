#include "semantics/descriptor/edge_distance.hpp"

#include <cmath>
#include <cstdint>
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

// out[x] = sqrt((x - v)^2 + g[v]^2) with v = nearest[x] (exact integers
// under the root; the loop vectorises).
FACADESLAM_KERNEL void root_distances(const float* g, const int* nearest, int width, float* out) {
  for (int x = 0; x < width; ++x) {
    const int v = nearest[x];
    const double dx = x - v;
    const double dy = g[v];
    out[x] = static_cast<float>(std::sqrt(dx * dx + dy * dy));
  }
}

// Exact squared distances along a row from the column distances (the lower
// envelope of parabolas of Felzenszwalb & Huttenlocher 2012), then roots.
// Everything is an integer (column distances, positions), so the envelope's
// breakpoints are kept as fractions and compared by cross-multiplication:
// no division in the loop, and no rounding.
struct RowBuffers {
  std::vector<int> sites, nearest;
  std::vector<std::int64_t> bound_num, bound_den;  // breakpoint k: bound_num[k] / bound_den[k], den > 0
};

void row_distances(const float* g, int width, float* out, RowBuffers& b) {
  const auto n = static_cast<std::size_t>(width);
  b.sites.resize(n);
  b.nearest.resize(n);
  b.bound_num.resize(n);
  b.bound_den.resize(n);
  const auto height = [&](int q) {
    const auto d = static_cast<std::int64_t>(g[q]);
    return d * d + static_cast<std::int64_t>(q) * q;
  };
  int k = -1;
  for (int q = 0; q < width; ++q) {
    if (g[q] >= kFar) continue;  // no edge in this column: not a parabola
    const std::int64_t hq = height(q);
    std::int64_t num = 0, den = 1;
    while (k >= 0) {
      const int v = b.sites[static_cast<std::size_t>(k)];
      num = hq - height(v);  // parabola q wins over v right of num / den
      den = 2 * static_cast<std::int64_t>(q - v);
      // Breakpoint 0 is minus infinity: q never removes the first parabola.
      if (k == 0 || num * b.bound_den[static_cast<std::size_t>(k)] > b.bound_num[static_cast<std::size_t>(k)] * den)
        break;
      --k;
    }
    ++k;
    b.sites[static_cast<std::size_t>(k)] = q;
    b.bound_num[static_cast<std::size_t>(k)] = num;
    b.bound_den[static_cast<std::size_t>(k)] = den;
  }
  int j = 0;
  for (int x = 0; x < width; ++x) {
    while (j < k && b.bound_num[static_cast<std::size_t>(j) + 1] < x * b.bound_den[static_cast<std::size_t>(j) + 1]) ++j;
    b.nearest[static_cast<std::size_t>(x)] = b.sites[static_cast<std::size_t>(j)];
  }
  root_distances(g, b.nearest.data(), width, out);
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
  RowBuffers buffers;
  for (int y = 0; y < edges.rows; ++y) row_distances(column.ptr<float>(y), edges.cols, distance.ptr<float>(y), buffers);
}

}  // namespace facadeslam::semantics
