#pragma once
// EDD's per-patch arithmetic (edd_descriptor.hpp), on a 9 x 9 patch of a
// plane whose pixels hold eight interleaved float channels:
//  - edd_patch_sums: per channel the largest value and the raw moments
//    S_pq = sum of x^p y^q v for p + q <= 3, x and y from the patch centre
//    (-4..4), in double: the eight channels are one vector, so these are
//    vector sums over the 81 pixels;
//  - edd_weighted_moments: mu30 mu21 mu12 mu03 of one channel weighted by
//    the normalised intensity I_norm = (max - v) / mean(max - v), from those
//    sums (a flat patch gets uniform weights, whose third-order moments are 0).
#include <cstddef>

namespace facadeslam::semantics {

inline constexpr int kEddRadius = 4;
inline constexpr int kEddSide = 2 * kEddRadius + 1;
inline constexpr int kEddArea = kEddSide * kEddSide;
inline constexpr int kEddChannels = 8;

struct EddPatchSums {
  // Row of S_pq in `raw`.
  static constexpr int kIndex[4][4] = {{0, 1, 2, 3}, {4, 5, 6, -1}, {7, 8, -1, -1}, {9, -1, -1, -1}};
  double raw[10][kEddChannels];
  float top[kEddChannels];

  double sum(int p, int q, int channel) const { return raw[kIndex[p][q]][channel]; }
  double mean(int channel) const { return sum(0, 0, channel) / kEddArea; }
};

// `top_left`: the patch's first pixel; rows `row_stride` floats apart.
void edd_patch_sums(const float* top_left, std::ptrdiff_t row_stride, EddPatchSums& out);

// mu30, mu21, mu12, mu03 of `channel` into out[0..3].
void edd_weighted_moments(const EddPatchSums& sums, int channel, float* out);

}  // namespace facadeslam::semantics
