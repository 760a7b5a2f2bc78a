#include "semantics/descriptor/modules/plane_statistics.hpp"

#include <algorithm>
#include <cmath>

#include "semantics/descriptor/kernel_support.hpp"

namespace facadeslam::semantics {
namespace {

template <int W>
[[gnu::always_inline]] inline MeanStd mean_std_lanes(const PatchView& patch) {
  const int n = patch.size();
  // Sums of deviations from the centre value keep float precision for
  // planes with a large offset (distances, angles); columns accumulate as
  // vector adds and are reduced once at the end.
  const float shift = patch.at(0, 0);
  alignas(32) float sum[W] = {};
  alignas(32) float squares[W] = {};
  for (int i = 0; i < n; ++i) {
    const float* row = patch.row(i);
    for (int x = 0; x < W; ++x) {
      const float d = row[x] - shift;
      sum[x] += d;
      squares[x] += d * d;
    }
  }
  double s = 0.0, q = 0.0;
  for (int x = 0; x < n; ++x) {  // lanes past the patch are ignored
    s += sum[x];
    q += squares[x];
  }
  const double count = static_cast<double>(n) * n;
  const double mean = s / count;
  return {shift + mean, std::sqrt(std::max(0.0, q / count - mean * mean))};
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
    const MeanStd stats = patch_mean_std(context.patch(planes[i]));
    if (want_mean) values[i] = static_cast<float>(stats.mean);
    if (want_std) values[k + i] = static_cast<float>(stats.std);
  }
}

}  // namespace facadeslam::semantics
