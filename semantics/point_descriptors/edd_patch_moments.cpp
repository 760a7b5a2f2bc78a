#include "semantics/point_descriptors/edd_patch_moments.hpp"

#include <array>
#include <cstring>

#include "semantics/descriptor/kernel_support.hpp"
#include "semantics/descriptor/modules/patch_moments.hpp"

namespace facadeslam::semantics {

static_assert(kEddChannels == kLanes, "a pixel's channels are one vector");

FACADESLAM_KERNEL
void edd_patch_sums(const float* top_left, std::ptrdiff_t row_stride, EddPatchSums& out) {
  using Halves = std::array<DoubleLanes, 2>;  // channels 0-3 and 4-7
  constexpr auto index = EddPatchSums::kIndex;
  FloatLanes top;
  load_lanes(top, top_left);
  Halves s[10] = {};
  for (int dy = 0; dy < kEddSide; ++dy) {
    const float* row = top_left + dy * row_stride;
    Halves by_x[4] = {};  // sums over the row of x^p v, p = 0..3
    for (int dx = 0; dx < kEddSide; ++dx) {
      FloatLanes v;
      load_lanes(v, row + kEddChannels * dx);
      top = v > top ? v : top;
      const Halves d = {__builtin_convertvector(__builtin_shufflevector(v, v, 0, 1, 2, 3), DoubleLanes),
                        __builtin_convertvector(__builtin_shufflevector(v, v, 4, 5, 6, 7), DoubleLanes)};
      const double x = dx - kEddRadius;
      for (int h = 0; h < 2; ++h) {
        by_x[0][h] += d[h];
        by_x[1][h] += x * d[h];
        by_x[2][h] += (x * x) * d[h];
        by_x[3][h] += (x * x * x) * d[h];
      }
    }
    const double y = dy - kEddRadius;
    for (int h = 0; h < 2; ++h) {
      for (int p = 0; p < 4; ++p) s[index[p][0]][h] += by_x[p][h];
      for (int p = 0; p < 3; ++p) s[index[p][1]][h] += y * by_x[p][h];
      for (int p = 0; p < 2; ++p) s[index[p][2]][h] += (y * y) * by_x[p][h];
      s[index[0][3]][h] += (y * y * y) * by_x[0][h];
    }
  }
  for (int m = 0; m < 10; ++m)
    for (int h = 0; h < 2; ++h) std::memcpy(&out.raw[m][4 * h], &s[m][h], sizeof s[m][h]);
  std::memcpy(out.top, &top, sizeof out.top);
}

// The weights' raw moments are (top G_pq - S_pq) / spread, with G_pq the
// patch grid's own moments about its centre: G00 = 81, G20 = G02 = 9 * sum
// of x^2 over -4..4, the others 0 by symmetry (raw[0][0] = 81 > 0);
// patch_moments then moves them to the weights' centroid.
void edd_weighted_moments(const EddPatchSums& sums, int channel, float* out) {
  constexpr double kSecond = kEddSide * (kEddRadius * (kEddRadius + 1) * (2 * kEddRadius + 1) / 3);
  constexpr double kGrid[4][4] = {{kEddArea, 0, kSecond, 0}, {0, 0, 0, 0}, {kSecond, 0, 0, 0}, {0, 0, 0, 0}};
  const double top = sums.top[channel];
  const double spread = top - sums.mean(channel);
  const bool flat = !(spread > 1e-9);
  const double inverse = flat ? 0.0 : 1.0 / spread;
  double raw[kMaxMomentOrder + 1][kMaxMomentOrder + 1];
#pragma GCC unroll 4
  for (int p = 0; p <= 3; ++p)
#pragma GCC unroll 4
    for (int q = 0; p + q <= 3; ++q)
      raw[p][q] = flat ? kGrid[p][q] : (top * kGrid[p][q] - sums.sum(p, q, channel)) * inverse;
  double mu[kMaxMomentOrder + 1][kMaxMomentOrder + 1];
  central_moments_from_raw(raw, 3, mu);
  out[0] = static_cast<float>(mu[3][0]);
  out[1] = static_cast<float>(mu[2][1]);
  out[2] = static_cast<float>(mu[1][2]);
  out[3] = static_cast<float>(mu[0][3]);
}

}  // namespace facadeslam::semantics
