#include "semantics/descriptor/modules/strip_sums.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "semantics/descriptor/kernel_support.hpp"
#include "semantics/descriptor/modules/gradient_angles_module.hpp"

namespace facadeslam::semantics {
namespace {

// Column sums of deviations from the centre row over rows -r..r, for the
// columns [0, count) of a span starting at `centre` (the centre row; rows
// `stride` floats apart). Blocks of 32 columns keep their sums in registers
// over all rows; every column adds its rows in the same order (vector lanes
// and the scalar tail alike), so a column's sums do not depend on the span.
FACADESLAM_KERNEL void deviation_sums(const float* centre, std::ptrdiff_t stride, int r, int count, float* sum,
                                      float* squares) {
  constexpr int kBlock = 4;           // vectors per block: 32 columns, two cache lines of each row
  constexpr int kPrefetchBlocks = 4;  // measured: 1 -> 4 took ~5 % off the thesis genome's extraction, 8 less
  int x = 0;
  for (; x + kBlock * kLanes <= count; x += kBlock * kLanes) {
    FloatLanes c[kBlock], s[kBlock] = {}, q[kBlock] = {};
    for (int b = 0; b < kBlock; ++b) load_lanes(c[b], centre + x + b * kLanes);
    for (int dy = -r; dy <= r; ++dy) {
      const float* row = centre + dy * stride + x;
      // The two lines of this row kPrefetchBlocks blocks ahead: 2r+1 rows
      // are more streams than the hardware prefetcher follows, and the
      // strips of a row's planes do not stay in L2 until the next row, so
      // the lines come from L3, further away than one block's work.
      __builtin_prefetch(row + kPrefetchBlocks * kBlock * kLanes);
      __builtin_prefetch(row + kPrefetchBlocks * kBlock * kLanes + 16);
      for (int b = 0; b < kBlock; ++b) {
        FloatLanes d;
        load_lanes(d, row + b * kLanes);
        d -= c[b];
        s[b] += d;
        q[b] += d * d;
      }
    }
    for (int b = 0; b < kBlock; ++b) {
      store_lanes(sum + x + b * kLanes, s[b]);
      store_lanes(squares + x + b * kLanes, q[b]);
    }
  }
  // The rest in single vectors; the last one may run up to 7 columns past
  // the span (planes carry PatchView::kReadSlack floats after each row, and
  // the sum arrays are as wide as the plane): those columns are junk that
  // their own span, computed later, overwrites. Every lane does the same
  // float operations as the blocks above, so results do not depend on
  // where a column falls in its span.
  for (; x < count; x += kLanes) {
    FloatLanes c, s = {}, q = {};
    load_lanes(c, centre + x);
    for (int dy = -r; dy <= r; ++dy) {
      FloatLanes d;
      load_lanes(d, centre + dy * stride + x);
      d -= c;
      s += d;
      q += d * d;
    }
    store_lanes(sum + x, s);
    store_lanes(squares + x, q);
  }
}

// Column sums of the r rows above and the r rows below the centre row
// (from the farthest row inward above, from the nearest outward below),
// blocked like deviation_sums.
FACADESLAM_KERNEL void half_sums(const float* centre, std::ptrdiff_t stride, int r, int count, float* top,
                                 float* bottom) {
  constexpr int kPrefetchBlocks = 8;  // blocks of 16 columns: the same 512 bytes ahead as deviation_sums
  int x = 0;
  for (; x + 2 * kLanes <= count; x += 2 * kLanes) {
    FloatLanes t[2] = {}, b[2] = {};
    for (int d = 1; d <= r; ++d) {
      const float* up = centre + (d - r - 1) * stride + x;
      const float* down = centre + d * stride + x;
      // Each row's line kPrefetchBlocks blocks ahead, as in deviation_sums.
      __builtin_prefetch(up + kPrefetchBlocks * 2 * kLanes);
      __builtin_prefetch(down + kPrefetchBlocks * 2 * kLanes);
      for (int k = 0; k < 2; ++k) {
        FloatLanes u, v;
        load_lanes(u, up + k * kLanes);
        load_lanes(v, down + k * kLanes);
        t[k] += u;
        b[k] += v;
      }
    }
    for (int k = 0; k < 2; ++k) {
      store_lanes(top + x + k * kLanes, t[k]);
      store_lanes(bottom + x + k * kLanes, b[k]);
    }
  }
  for (; x < count; x += kLanes) {  // single vectors, past the span as in deviation_sums
    FloatLanes t = {}, b = {};
    for (int d = 1; d <= r; ++d) {
      FloatLanes u, v;
      load_lanes(u, centre + (d - r - 1) * stride + x);
      load_lanes(v, centre + d * stride + x);
      t += u;
      b += v;
    }
    store_lanes(top + x, t);
    store_lanes(bottom + x, b);
  }
}

// From deviations d = v - c over n rows: sum v = sum d + n c, sum v^2 =
// sum d^2 + 2 c sum d + n c^2.
FACADESLAM_KERNEL void plain_sums(const float* sum, const float* squares, const float* centre, int n, double* total,
                                  double* total_squares, int count) {
  for (int x = 0; x < count; ++x) {
    const double c = centre[x];
    total[x] = sum[x] + n * c;
    total_squares[x] = squares[x] + c * (2.0 * sum[x] + n * c);
  }
}

// Mean and sigma of a patch from its n column totals, added in a fixed
// order (four-lane vector partial sums, then the lanes), the same for every
// keypoint.
FACADESLAM_KERNEL MeanStd window_mean_std(const double* total, const double* total_squares, int n) {
  DoubleLanes sum = {}, squares = {};
  int x = 0;
  for (; x + 4 <= n; x += 4) {
    DoubleLanes t, q;
    std::memcpy(&t, total + x, sizeof t);
    std::memcpy(&q, total_squares + x, sizeof q);
    sum += t;
    squares += q;
  }
  double s = (sum[0] + sum[1]) + (sum[2] + sum[3]);
  double q = (squares[0] + squares[1]) + (squares[2] + squares[3]);
  for (; x < n; ++x) {
    s += total[x];
    q += total_squares[x];
  }
  const double count = static_cast<double>(n) * n;
  const double mean = s / count;
  return {mean, std::sqrt(std::max(0.0, q / count - mean * mean))};
}

}  // namespace

void StripSums::configure(const PreparedImage& image, int radius, PlaneSet statistics, PlaneSet regions,
                          const std::array<int, 3>& moment_order) {
  CV_Assert(radius >= 1 && radius <= image.border && (statistics & regions).none() &&
            (image.computed & (statistics | regions)) == (statistics | regions));
  image_ = &image;
  radius_ = radius;
  statistics_ = statistics;
  regions_ = regions;
  moment_order_ = moment_order;
  row_ = -1;
  for (int c = 0; c < 3; ++c) {
    const int order = moment_order[static_cast<std::size_t>(c)];
    if (order < 0) continue;
    CV_Assert(order <= kMaxMomentOrder && image.has(colour_plane(c)));
    const auto bit = plane_bit(colour_plane(c));
    // As wide as the plane plus the read slack: moment_column_sums writes
    // whole blocks, up to 7 columns past a span.
    const auto width = static_cast<std::size_t>(image.planes[bit].cols + PatchView::kReadSlack);
    columns_[bit].moments.resize(width * kMomentColumnStride);
  }
  for (int p = 0; p < kPlaneCount; ++p) {
    const auto bit = static_cast<std::size_t>(p);
    if (!statistics.test(bit) && !regions.test(bit)) continue;
    const auto width = static_cast<std::size_t>(image.planes[bit].cols);
    Columns& c = columns_[bit];
    if (statistics.test(bit)) {
      c.sum.resize(width);
      c.squares.resize(width);
      c.total.resize(width);
      c.total_squares.resize(width);
    }
    if (regions.test(bit)) {
      c.top.resize(width);
      c.bottom.resize(width);
    }
  }
}

void StripSums::compute_statistics(const cv::Mat& plane, int first, int last, Columns& c) const {
  const int count = last - first;
  const float* centre = plane.ptr<float>(row_ + image_->border) + first;
  const auto stride = static_cast<std::ptrdiff_t>(plane.step1());
  deviation_sums(centre, stride, radius_, count, c.sum.data() + first, c.squares.data() + first);
  plain_sums(c.sum.data() + first, c.squares.data() + first, centre, 2 * radius_ + 1, c.total.data() + first,
             c.total_squares.data() + first, count);
}

void StripSums::compute_regions(const cv::Mat& plane, int first, int last, Columns& c) const {
  const int count = last - first;
  const float* centre = plane.ptr<float>(row_ + image_->border) + first;
  half_sums(centre, static_cast<std::ptrdiff_t>(plane.step1()), radius_, count, c.top.data() + first,
            c.bottom.data() + first);
}

void StripSums::compute_moments(const cv::Mat& plane, int order, int first, int last, Columns& c) const {
  const float* centre = plane.ptr<float>(row_ + image_->border) + first;
  moment_column_sums(centre, static_cast<std::ptrdiff_t>(plane.step1()), radius_, order, last - first,
                     c.moments.data() + kMomentColumnStride * static_cast<std::size_t>(first));
}

void StripSums::compute(int row, const std::vector<int>& centres) {
  CV_Assert(image_ && row >= 0 && row < image_->image_size.height);
  row_ = row;
  spans_.clear();
  for (const int x : centres) {
    const int first = x + image_->border - radius_, last = x + image_->border + radius_ + 1;
    if (!spans_.empty() && first <= spans_.back().second)
      spans_.back().second = std::max(spans_.back().second, last);
    else
      spans_.emplace_back(first, last);
  }
  for (int p = 0; p < kPlaneCount; ++p) {
    const auto bit = static_cast<std::size_t>(p);
    const cv::Mat& plane = image_->planes[bit];
    for (const auto& [first, last] : spans_) {
      if (statistics_.test(bit))
        compute_statistics(plane, first, last, columns_[bit]);
      else if (regions_.test(bit))
        compute_regions(plane, first, last, columns_[bit]);
    }
  }
  for (int c = 0; c < 3; ++c) {
    const int order = moment_order_[static_cast<std::size_t>(c)];
    if (order < 0) continue;
    const auto bit = plane_bit(colour_plane(c));
    for (const auto& [first, last] : spans_) compute_moments(image_->planes[bit], order, first, last, columns_[bit]);
  }
}

void StripSums::moments(int channel, int x, PatchMoments& out) const {
  const int order = moment_order_[static_cast<std::size_t>(channel)];
  CV_Assert(order >= 0);
  const Columns& c = columns_[plane_bit(colour_plane(channel))];
  const auto first = static_cast<std::size_t>(x + image_->border - radius_);
  patch_moments_from_columns(c.moments.data() + kMomentColumnStride * first, radius_, order, out);
}

MeanStd StripSums::mean_std(PlaneId p, int x) const {
  const Columns& c = columns_[plane_bit(p)];
  const auto first = static_cast<std::size_t>(x + image_->border - radius_);
  return window_mean_std(c.total.data() + first, c.total_squares.data() + first, 2 * radius_ + 1);
}

std::array<double, 5> StripSums::region_means(PlaneId p, int x) const {
  const Columns& c = columns_[plane_bit(p)];
  const int first = x + image_->border - radius_;
  const float* middle = image_->planes[plane_bit(p)].ptr<float>(row_ + image_->border) + first;
  return region_means_from_columns(c.top.data() + first, c.bottom.data() + first, middle, radius_);
}

}  // namespace facadeslam::semantics
