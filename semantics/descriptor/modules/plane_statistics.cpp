#include "semantics/descriptor/modules/plane_statistics.hpp"

#include <algorithm>
#include <cmath>

#include "semantics/descriptor/kernel_support.hpp"

namespace facadeslam::semantics {
namespace {

template <int W>
[[gnu::always_inline]] inline MeanStd mean_std_lanes(const PatchView& patch) {
  constexpr int kBlocks = W / kLanes;
  const int n = patch.size();
  // Sums of deviations from the centre value keep float precision for
  // planes with a large offset (distances, angles). Even and odd rows go to
  // separate accumulators (twice the independent adds in flight); lanes
  // past the patch are masked once at the end.
  const float shift = patch.at(0, 0);
  const FloatLanes shifts = FloatLanes{} + shift;
  FloatLanes sum[2][kBlocks] = {}, squares[2][kBlocks] = {};
  const auto add_row = [&](const float* row, FloatLanes* row_sum, FloatLanes* row_squares) {
    for (int b = 0; b < kBlocks; ++b) {
      FloatLanes d;
      load_lanes(d, row + b * kLanes);
      d -= shifts;
      row_sum[b] += d;
      row_squares[b] += d * d;
    }
  };
  int i = 0;
  for (; i + 1 < n; i += 2) {
    add_row(patch.row(i), sum[0], squares[0]);
    add_row(patch.row(i + 1), sum[1], squares[1]);
  }
  if (i < n) add_row(patch.row(i), sum[0], squares[0]);
  FloatLanes s = {}, q = {};
  for (int b = 0; b < kBlocks; ++b) {
    FloatLanes block_sum = sum[0][b] + sum[1][b], block_squares = squares[0][b] + squares[1][b];
    keep_below(block_sum, b * kLanes, n);
    keep_below(block_squares, b * kLanes, n);
    s += block_sum;
    q += block_squares;
  }
  const double count = static_cast<double>(n) * n;
  const double mean = lane_sum(s) / count;
  return {shift + mean, std::sqrt(std::max(0.0, lane_sum(q) / count - mean * mean))};
}

}  // namespace

FACADESLAM_KERNEL
MeanStd patch_mean_std(const PatchView& patch) {
  switch (lane_width(patch.size())) {
    case 8: return mean_std_lanes<8>(patch);
    case 16: return mean_std_lanes<16>(patch);
    case 24: return mean_std_lanes<24>(patch);
    default: break;
  }
  CV_Error(cv::Error::StsOutOfRange, "patch radius exceeds the kernels' 10 pixels");
}

void mean_std_values(const ModuleContext& context, const PlaneId* planes, int k, std::uint64_t bits, float* values) {
  for (int i = 0; i < k; ++i) {
    const bool want_mean = bit_set(bits, i);
    const bool want_std = bit_set(bits, k + i);
    if (!want_mean && !want_std) continue;
    const MeanStd stats = context.mean_std(planes[i]);
    if (want_mean) values[i] = static_cast<float>(stats.mean);
    if (want_std) values[k + i] = static_cast<float>(stats.std);
  }
}

}  // namespace facadeslam::semantics
