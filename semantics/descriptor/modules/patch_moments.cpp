#include "semantics/descriptor/modules/patch_moments.hpp"

#include <cmath>
#include <cstring>

#include <opencv2/core.hpp>

#include "semantics/descriptor/descriptor_params.hpp"
#include "semantics/descriptor/kernel_support.hpp"

namespace facadeslam::semantics {
namespace {

constexpr double kBinomial[6][6] = {{1, 0, 0, 0, 0, 0}, {1, 1, 0, 0, 0, 0}, {1, 2, 1, 0, 0, 0},
                                    {1, 3, 3, 1, 0, 0}, {1, 4, 6, 4, 1, 0}, {1, 5, 10, 10, 5, 1}};
constexpr int kMaxOrder = kMaxMomentOrder;

// column[q] = sum over rows y of y^q I(x, y), y from the centre row, for the
// eight columns x from `centre` (a pointer into the centre row). Rows y and
// -y are folded first: even powers weight their sum, odd powers their
// difference, which halves the multiply-adds. The order is a template
// parameter so that every loop has a fixed trip count. The patch kernel and
// the strip (moment_column_sums) both call this, so a column's sums are the
// same bits either way.
template <int Order>
[[gnu::always_inline]] inline void column_block(const float* centre, std::ptrdiff_t stride, int r,
                                                FloatLanes* column) {
  load_lanes(column[0], centre);
  for (int q = 1; q <= Order; ++q) column[q] = FloatLanes{};
  for (int d = 1; d <= r; ++d) {
    float weights[Order + 1];
    weights[0] = 1.0f;
    for (int q = 1; q <= Order; ++q) weights[q] = weights[q - 1] * static_cast<float>(d);
    FloatLanes lower, upper;
    load_lanes(lower, centre + d * stride);   // y = +d
    load_lanes(upper, centre - d * stride);   // y = -d
    const FloatLanes even = lower + upper;
    const FloatLanes odd = lower - upper;
    for (int q = 0; q <= Order; ++q) column[q] += weights[q] * ((q & 1) ? odd : even);
  }
}

// Powers d^p of the column offsets d = 0..10, split by the parity of p
// (lanes p = 0, 2, 4 and p = 1, 3, 5; the fourth lane is unused), so that
// the horizontal pass is two vector multiply-adds per column pair.
struct OffsetPowers {
  DoubleLanes even[kMaxPatchRadius + 1], odd[kMaxPatchRadius + 1];
};
constexpr OffsetPowers make_offset_powers() {
  OffsetPowers t{};
  for (int d = 0; d <= kMaxPatchRadius; ++d) {
    const double v = d;
    t.even[d] = DoubleLanes{1.0, v * v, v * v * v * v, 0.0};
    t.odd[d] = DoubleLanes{v, v * v * v, v * v * v * v * v, 0.0};
  }
  return t;
}
constexpr OffsetPowers kOffsetPowers = make_offset_powers();

// raw[p][q] = sum_x x^p columns[q][x] over the 2r+1 columns (columns[q]
// points at the patch's first column), folded the same way in x: even p
// weight the sum of columns +d and -d, odd p their difference.
template <int Order>
[[gnu::always_inline]] inline void horizontal_moments(const float* const* columns, int r,
                                                      double (*raw)[kMaxOrder + 1]) {
  for (int q = 0; q <= Order; ++q) {
    const float* col = columns[q];
    DoubleLanes even_p = {static_cast<double>(col[r]), 0.0, 0.0, 0.0};  // x = 0 counts for p = 0 only
    DoubleLanes odd_p = {};
    for (int d = 1; d <= r; ++d) {
      const double right = col[r + d], left = col[r - d];
      even_p += kOffsetPowers.even[d] * (right + left);
      odd_p += kOffsetPowers.odd[d] * (right - left);
    }
    for (int p = 0; p + q <= Order; ++p) raw[p][q] = (p & 1) ? odd_p[p / 2] : even_p[p / 2];
  }
}

template <int Order, int W>
[[gnu::always_inline]] inline void raw_moments(const PatchView& patch, double (*raw)[kMaxOrder + 1]) {
  constexpr int kBlocks = W / kLanes;
  const int r = patch.radius;
  alignas(32) float column[Order + 1][W];
  for (int b = 0; b < kBlocks; ++b) {
    FloatLanes block[Order + 1];
    column_block<Order>(patch.row(r) + b * kLanes, patch.stride, r, block);
    for (int q = 0; q <= Order; ++q) store_lanes(column[q] + b * kLanes, block[q]);
  }
  const float* columns[Order + 1];
  for (int q = 0; q <= Order; ++q) columns[q] = column[q];
  horizontal_moments<Order>(columns, r, raw);
}

// Moves the origin to the centroid, one axis at a time (the binomial
// expansion of (x - cx)^p (y - cy)^q is separable).
template <int Order>
[[gnu::always_inline]] inline void central_moments(const double (*raw)[kMaxOrder + 1], double cx, double cy,
                                                   double (*mu)[kMaxOrder + 1]) {
  double px[Order + 1], py[Order + 1];  // powers of -cx, -cy
  px[0] = py[0] = 1.0;
  for (int k = 1; k <= Order; ++k) {
    px[k] = px[k - 1] * -cx;
    py[k] = py[k - 1] * -cy;
  }
  double shifted[Order + 1][Order + 1];  // only p + q <= Order is written and read
  for (int q = 0; q <= Order; ++q)
    for (int p = 0; p + q <= Order; ++p) {
      double sum = 0.0;
      for (int i = 0; i <= p; ++i) sum += kBinomial[p][i] * px[p - i] * raw[i][q];
      shifted[p][q] = sum;
    }
  for (int p = 0; p <= Order; ++p)
    for (int q = 0; p + q <= Order; ++q) {
      double sum = 0.0;
      for (int j = 0; j <= q; ++j) sum += kBinomial[q][j] * py[q - j] * shifted[p][j];
      mu[p][q] = sum;
    }
}

// Central and normalised moments from the raw ones (into out; every entry
// up to Order is written).
template <int Order>
[[gnu::always_inline]] inline void moments_from_raw(const double (*raw)[kMaxOrder + 1], PatchMoments& out) {
  const double m00 = raw[0][0];
  if (!(m00 > 0.0)) {  // no mass: every moment is 0
    out = PatchMoments{};
    out.order = Order;
    return;
  }
  const double cx = Order >= 1 ? raw[1][0] / m00 : 0.0;
  const double cy = Order >= 1 ? raw[0][1] / m00 : 0.0;
  central_moments<Order>(raw, cx, cy, out.mu);
  if (Order >= 1) out.mu[1][0] = out.mu[0][1] = 0.0;  // zero by definition, rounding aside

  const double root = std::sqrt(m00);
  double scale = 1.0 / m00;
  for (int k = 0; k <= kMaxOrder; ++k) {
    out.eta_scale[k] = scale;
    scale /= root;
  }
  out.mass_powers[0] = 1.0;
  for (int k = 1; k < 15; ++k) out.mass_powers[k] = out.mass_powers[k - 1] * m00;
}

template <int Order>
[[gnu::always_inline]] inline void moments_of_order(const PatchView& patch, PatchMoments& out) {
  double raw[kMaxOrder + 1][kMaxOrder + 1];  // only p + q <= Order is written and read
  switch (lane_width(patch.size())) {
    case 8: raw_moments<Order, 8>(patch, raw); break;
    case 16: raw_moments<Order, 16>(patch, raw); break;
    case 24: raw_moments<Order, 24>(patch, raw); break;
    default: CV_Error(cv::Error::StsOutOfRange, "patch radius exceeds the kernels' 10 pixels");
  }
  moments_from_raw<Order>(raw, out);
}

template <int Order>
[[gnu::always_inline]] inline void moments_of_columns(const float* const* columns, int r, PatchMoments& out) {
  double raw[kMaxOrder + 1][kMaxOrder + 1];
  horizontal_moments<Order>(columns, r, raw);
  moments_from_raw<Order>(raw, out);
}

template <int Order>
[[gnu::always_inline]] inline void column_sums_of_order(const float* centre, std::ptrdiff_t stride, int r, int count,
                                                        float* const* columns) {
  for (int x = 0; x < count; x += kLanes) {
    FloatLanes block[Order + 1];
    column_block<Order>(centre + x, stride, r, block);
    for (int q = 0; q <= Order; ++q) store_lanes(columns[q] + x, block[q]);
  }
}

}  // namespace

FACADESLAM_KERNEL
void compute_patch_moments(const PatchView& patch, int order, PatchMoments& out) {
  // Not cleared first: every entry up to `order` is written below (clearing
  // the whole struct cost more than the low orders themselves).
  out.order = order;
  switch (order) {
    case 0: return moments_of_order<0>(patch, out);
    case 1: return moments_of_order<1>(patch, out);
    case 2: return moments_of_order<2>(patch, out);
    case 3: return moments_of_order<3>(patch, out);
    case 4: return moments_of_order<4>(patch, out);
    case 5: return moments_of_order<5>(patch, out);
    default: break;
  }
  CV_Error(cv::Error::StsOutOfRange, "moment order must be 0..5");
}

FACADESLAM_KERNEL
void moment_column_sums(const float* centre, std::ptrdiff_t stride, int r, int order, int count,
                        float* const* columns) {
  switch (order) {
    case 0: return column_sums_of_order<0>(centre, stride, r, count, columns);
    case 1: return column_sums_of_order<1>(centre, stride, r, count, columns);
    case 2: return column_sums_of_order<2>(centre, stride, r, count, columns);
    case 3: return column_sums_of_order<3>(centre, stride, r, count, columns);
    case 4: return column_sums_of_order<4>(centre, stride, r, count, columns);
    case 5: return column_sums_of_order<5>(centre, stride, r, count, columns);
    default: break;
  }
  CV_Error(cv::Error::StsOutOfRange, "moment order must be 0..5");
}

FACADESLAM_KERNEL
void patch_moments_from_columns(const float* const* columns, int r, int order, PatchMoments& out) {
  out.order = order;
  switch (order) {
    case 0: return moments_of_columns<0>(columns, r, out);
    case 1: return moments_of_columns<1>(columns, r, out);
    case 2: return moments_of_columns<2>(columns, r, out);
    case 3: return moments_of_columns<3>(columns, r, out);
    case 4: return moments_of_columns<4>(columns, r, out);
    case 5: return moments_of_columns<5>(columns, r, out);
    default: break;
  }
  CV_Error(cv::Error::StsOutOfRange, "moment order must be 0..5");
}

}  // namespace facadeslam::semantics
