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
[[gnu::always_inline]] inline void column_block(const float* centre, std::ptrdiff_t stride, int r, FloatLanes* column) {
  load_lanes(column[0], centre);
  for (int q = 1; q <= Order; ++q) column[q] = FloatLanes{};
  for (int d = 1; d <= r; ++d) {
    float weights[Order + 1];
    weights[0] = 1.0f;
    for (int q = 1; q <= Order; ++q) weights[q] = weights[q - 1] * static_cast<float>(d);
    FloatLanes lower, upper;
    load_lanes(lower, centre + d * stride);  // y = +d
    load_lanes(upper, centre - d * stride);  // y = -d
    const FloatLanes even = lower + upper;
    const FloatLanes odd = lower - upper;
    for (int q = 0; q <= Order; ++q) column[q] += weights[q] * ((q & 1) ? odd : even);
  }
}

// Powers d^p of the column offsets d = 0..10, p = 0..5.
struct OffsetPowers {
  double power[kMaxPatchRadius + 1][kMaxOrder + 1];
};
constexpr OffsetPowers make_offset_powers() {
  OffsetPowers t{};
  for (int d = 0; d <= kMaxPatchRadius; ++d) {
    t.power[d][0] = 1.0;
    for (int p = 1; p <= kMaxOrder; ++p) t.power[d][p] = t.power[d][p - 1] * d;
  }
  return t;
}
constexpr OffsetPowers kOffsetPowers = make_offset_powers();

// Column sums are kept interleaved, a column's sums for q = 0..7 in one
// vector (columns[kMomentColumnStride * x + q], zero past the order), so
// that the horizontal pass updates all q at once.
static_assert(kMaxOrder + 1 <= kMomentColumnStride && kMomentColumnStride == kLanes);

// The block of column sums column_block made (block[q] over 8 columns),
// interleaved into out[kMomentColumnStride * k + q] for its columns k = 0..7.
template <int Order>
[[gnu::always_inline]] inline void store_interleaved(const FloatLanes* block, float* out) {
  FloatLanes rows[kLanes];
  for (int q = 0; q < kLanes; ++q) rows[q] = q <= Order ? block[q] : FloatLanes{};
  transpose_lanes(rows);
  for (int k = 0; k < kLanes; ++k) store_lanes(out + kMomentColumnStride * k, rows[k]);
}

// raw[p][q] = sum_x x^p column_q(x) over the 2r+1 columns (`columns` points
// at the patch's first column, interleaved), folded in x: even p weight the
// sum of columns +d and -d, odd p their difference. Double accumulators,
// four q per vector; every raw[p][q] is the same chain of multiply-adds it
// would be alone.
template <int Order>
[[gnu::always_inline]] inline void horizontal_moments(const float* columns, int r, double (*raw)[kMaxOrder + 1]) {
  using FourFloats = float __attribute__((vector_size(4 * sizeof(float))));
  constexpr int kHalves = Order >= 4 ? 2 : 1;  // q = 0..3, then 4..7
  const auto load = [&](int column, int half, DoubleLanes& out) {
    FourFloats four;
    std::memcpy(&four, columns + kMomentColumnStride * column + 4 * half, sizeof four);
    out = __builtin_convertvector(four, DoubleLanes);
  };
  DoubleLanes sums[Order + 1][kHalves] = {};
  for (int h = 0; h < kHalves; ++h) load(r, h, sums[0][h]);  // x = 0 counts for p = 0 only
  for (int d = 1; d <= r; ++d) {
    const double* power = kOffsetPowers.power[d];
    for (int h = 0; h < kHalves; ++h) {
      DoubleLanes right, left;
      load(r + d, h, right);
      load(r - d, h, left);
      const DoubleLanes even = right + left, odd = right - left;
      for (int p = 0; p <= Order; ++p)
        if (p + 4 * h <= Order) sums[p][h] += power[p] * ((p & 1) ? odd : even);
    }
  }
  for (int p = 0; p <= Order; ++p)
    for (int q = 0; p + q <= Order; ++q) raw[p][q] = sums[p][q / 4][q % 4];
}

template <int Order, int W>
[[gnu::always_inline]] inline void raw_moments(const PatchView& patch, double (*raw)[kMaxOrder + 1]) {
  constexpr int kBlocks = W / kLanes;
  const int r = patch.radius;
  alignas(32) float columns[W * kMomentColumnStride];
  for (int b = 0; b < kBlocks; ++b) {
    FloatLanes block[Order + 1];
    column_block<Order>(patch.row(r) + b * kLanes, patch.stride, r, block);
    store_interleaved<Order>(block, columns + kMomentColumnStride * kLanes * b);
  }
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
  // The triangular loops are unrolled (Order is a constant): rolled, their
  // bookkeeping cost as much as the multiply-adds.
  double shifted[Order + 1][Order + 1];  // only p + q <= Order is written and read
#pragma GCC unroll 6
  for (int q = 0; q <= Order; ++q)
#pragma GCC unroll 6
    for (int p = 0; p + q <= Order; ++p) {
      double sum = 0.0;
#pragma GCC unroll 6
      for (int i = 0; i <= p; ++i) sum += kBinomial[p][i] * px[p - i] * raw[i][q];
      shifted[p][q] = sum;
    }
#pragma GCC unroll 6
  for (int p = 0; p <= Order; ++p)
#pragma GCC unroll 6
    for (int q = 0; p + q <= Order; ++q) {
      double sum = 0.0;
#pragma GCC unroll 6
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
[[gnu::always_inline]] inline void moments_of_columns(const float* columns, int r, PatchMoments& out) {
  double raw[kMaxOrder + 1][kMaxOrder + 1];
  horizontal_moments<Order>(columns, r, raw);
  moments_from_raw<Order>(raw, out);
}

template <int Order>
[[gnu::always_inline]] inline void column_sums_of_order(const float* centre, std::ptrdiff_t stride, int r, int count,
                                                        float* columns) {
  for (int x = 0; x < count; x += kLanes) {
    FloatLanes block[Order + 1];
    column_block<Order>(centre + x, stride, r, block);
    store_interleaved<Order>(block, columns + kMomentColumnStride * x);
  }
}

// f.template operator()<Order>() for Order = order (0..5): the kernels take
// the order as a template parameter, for fixed trip counts. `f` is an
// always-inline lambda, so it is compiled for the caller's clone.
template <class F>
[[gnu::always_inline]] inline void with_order(int order, const F& f) {
  switch (order) {
    case 0: return f.template operator()<0>();
    case 1: return f.template operator()<1>();
    case 2: return f.template operator()<2>();
    case 3: return f.template operator()<3>();
    case 4: return f.template operator()<4>();
    case 5: return f.template operator()<5>();
    default: break;
  }
  CV_Error(cv::Error::StsOutOfRange, "moment order must be 0..5");
}

}  // namespace

FACADESLAM_KERNEL
void compute_patch_moments(const PatchView& patch, int order, PatchMoments& out) {
  // Not cleared first: every entry up to `order` is written below (clearing
  // the whole struct cost more than the low orders themselves).
  out.order = order;
  with_order(
      order, [&]<int Order>() __attribute__((always_inline)) { moments_of_order<Order>(patch, out); });
}

FACADESLAM_KERNEL
void moment_column_sums(const float* centre, std::ptrdiff_t stride, int r, int order, int count, float* columns) {
  with_order(
      order, [&]<int Order>()
                 __attribute__((always_inline)) { column_sums_of_order<Order>(centre, stride, r, count, columns); });
}

FACADESLAM_KERNEL
void patch_moments_from_columns(const float* columns, int r, int order, PatchMoments& out) {
  out.order = order;
  with_order(
      order, [&]<int Order>() __attribute__((always_inline)) { moments_of_columns<Order>(columns, r, out); });
}

void central_moments_from_raw(const double (*raw)[kMaxMomentOrder + 1], int order, double (*mu)[kMaxMomentOrder + 1]) {
  const double cx = raw[1][0] / raw[0][0], cy = raw[0][1] / raw[0][0];
  with_order(
      order, [&]<int Order>() __attribute__((always_inline)) { central_moments<Order>(raw, cx, cy, mu); });
}

}  // namespace facadeslam::semantics
