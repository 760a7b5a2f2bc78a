#include "semantics/descriptor/edge_distance.hpp"

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

// Exact squared distances along a row from the column distances (the lower
// envelope of parabolas of Felzenszwalb & Huttenlocher 2012), then roots.
void row_distances(const float* g, int width, float* out, std::vector<int>& sites, std::vector<double>& bounds) {
  sites.resize(static_cast<std::size_t>(width));
  bounds.resize(static_cast<std::size_t>(width) + 1);
  const auto height = [&](int q) { return static_cast<double>(g[q]) * g[q] + static_cast<double>(q) * q; };
  int k = -1;
  for (int q = 0; q < width; ++q) {
    if (g[q] >= kFar) continue;  // no edge in this column: not a parabola
    double s = -std::numeric_limits<double>::infinity();
    while (k >= 0) {
      const int v = sites[static_cast<std::size_t>(k)];
      s = (height(q) - height(v)) / (2.0 * (q - v));  // where parabola q starts to win over v
      if (s > bounds[static_cast<std::size_t>(k)]) break;
      --k;
    }
    ++k;
    sites[static_cast<std::size_t>(k)] = q;
    bounds[static_cast<std::size_t>(k)] = k == 0 ? -std::numeric_limits<double>::infinity() : s;
  }
  bounds[static_cast<std::size_t>(k) + 1] = std::numeric_limits<double>::infinity();
  int j = 0;
  for (int x = 0; x < width; ++x) {
    while (bounds[static_cast<std::size_t>(j) + 1] < x) ++j;
    const int v = sites[static_cast<std::size_t>(j)];
    const double dx = x - v;
    out[x] = static_cast<float>(std::sqrt(dx * dx + static_cast<double>(g[v]) * g[v]));
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
  std::vector<int> sites;
  std::vector<double> bounds;
  for (int y = 0; y < edges.rows; ++y) row_distances(column.ptr<float>(y), edges.cols, distance.ptr<float>(y), sites, bounds);
}

}  // namespace facadeslam::semantics
