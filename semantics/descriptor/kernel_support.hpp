#pragma once
// Helpers for the hot loops: the per-patch kernels of extraction and the
// per-pixel passes of preprocessing.
//
// Row width: kernels read patch rows in blocks of kLanes floats, rounding the
// patch width 2r+1 up (lane_width), so that their inner loops have a fixed
// trip count the compiler turns into straight vector code. The extra columns
// are real pixels of the plane or its zeroed slack (padded_plane.hpp,
// PatchView::kReadSlack); kernels ignore their results.
//
// The helpers below are always inlined, so that the code they expand to is
// compiled for the target of the kernel that uses them.
//
// FACADESLAM_KERNEL: on x86-64 with GCC, the function is also compiled
// for AVX2 (x86-64-v3) and AVX-512 (x86-64-v4), and the best version the
// CPU runs is chosen when the program loads; elsewhere it is an ordinary
// function. The v4 clone runs the same 8-lane code, with 32 vector
// registers instead of 16 (fewer spills in the wide kernels: ~8 % on the
// thesis genome on a Zen 4). All versions compute the same formulas; float
// rounding may differ in the last bits between CPUs.
#include <cstring>

#include "semantics/descriptor/fast_math.hpp"

namespace facadeslam::semantics {

inline constexpr int kLanes = 8;

// 2r+1 rounded up to a multiple of kLanes (8, 16 or 24 for r <= 10).
constexpr int lane_width(int size) { return (size + kLanes - 1) / kLanes * kLanes; }

// kLanes floats as one vector (GCC/Clang vector extension: 2 SSE registers
// by default, one AVX register in the x86-64-v3 clone). Helpers take and
// return vectors by reference: passing them by value would depend on the
// target's ABI.
using FloatLanes = float __attribute__((vector_size(kLanes * sizeof(float))));
using IntLanes = int __attribute__((vector_size(kLanes * sizeof(int))));
// Four doubles: one AVX register, for the passes that accumulate in double.
using DoubleLanes = double __attribute__((vector_size(4 * sizeof(double))));

[[gnu::always_inline]] inline void load_lanes(FloatLanes& v, const float* p) { std::memcpy(&v, p, sizeof v); }
[[gnu::always_inline]] inline void store_lanes(float* p, const FloatLanes& v) { std::memcpy(p, &v, sizeof v); }
// Sum of the lanes by halving (3 shuffle-adds instead of 7 dependent adds).
[[gnu::always_inline]] inline float lane_sum(const FloatLanes& v) {
  using Four = float __attribute__((vector_size(4 * sizeof(float))));
  Four low, high;
  std::memcpy(&low, &v, sizeof low);
  std::memcpy(&high, reinterpret_cast<const char*>(&v) + sizeof low, sizeof high);
  const Four four = low + high;
  const Four two = four + __builtin_shufflevector(four, four, 2, 3, 0, 1);
  const Four one = two + __builtin_shufflevector(two, two, 1, 0, 3, 2);
  return one[0];
}
// Zeroes the lanes whose index first + j is not below `size`.
[[gnu::always_inline]] inline void keep_below(FloatLanes& v, int first, int size) {
  const IntLanes lane = {0, 1, 2, 3, 4, 5, 6, 7};
  const IntLanes keep = (lane + first) < size;  // all bits set where true
  IntLanes bits;
  std::memcpy(&bits, &v, sizeof bits);
  bits &= keep;
  std::memcpy(&v, &bits, sizeof v);
}
static_assert(kLanes == 8, "keep_below lists the lane indices");

// The 8 x 8 block rows[0..7] transposed in place: rows[k] becomes column k
// (three rounds of two-source shuffles: unpack, 64-bit pairs, 128-bit halves).
[[gnu::always_inline]] inline void transpose_lanes(FloatLanes* rows) {
  FloatLanes t[kLanes], s[kLanes];
  for (int k = 0; k < 4; ++k) {
    t[2 * k] = __builtin_shufflevector(rows[2 * k], rows[2 * k + 1], 0, 8, 1, 9, 4, 12, 5, 13);
    t[2 * k + 1] = __builtin_shufflevector(rows[2 * k], rows[2 * k + 1], 2, 10, 3, 11, 6, 14, 7, 15);
  }
  for (int h = 0; h < 2; ++h) {  // rows 0-3, then 4-7
    const FloatLanes* u = t + 4 * h;
    FloatLanes* o = s + 4 * h;
    o[0] = __builtin_shufflevector(u[0], u[2], 0, 1, 8, 9, 4, 5, 12, 13);
    o[1] = __builtin_shufflevector(u[0], u[2], 2, 3, 10, 11, 6, 7, 14, 15);
    o[2] = __builtin_shufflevector(u[1], u[3], 0, 1, 8, 9, 4, 5, 12, 13);
    o[3] = __builtin_shufflevector(u[1], u[3], 2, 3, 10, 11, 6, 7, 14, 15);
  }
  for (int k = 0; k < 4; ++k) {
    rows[k] = __builtin_shufflevector(s[k], s[k + 4], 0, 1, 2, 3, 8, 9, 10, 11);
    rows[k + 4] = __builtin_shufflevector(s[k], s[k + 4], 4, 5, 6, 7, 12, 13, 14, 15);
  }
}
static_assert(kLanes == 8, "transpose_lanes is an 8 x 8 transpose");

}  // namespace facadeslam::semantics

// No clones under ThreadSanitizer: the clones' ifunc resolvers run while the
// dynamic loader relocates the program, before the TSan runtime is set up,
// and the instrumented resolver crashes there (seen in test_slam once the
// semantic worker linked the descriptor in).
#if defined(__GNUC__) && !defined(__clang__) && defined(__x86_64__) && !defined(FACADESLAM_NO_KERNEL_CLONES) && \
    !defined(__SANITIZE_THREAD__)
#define FACADESLAM_KERNEL __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#else
#define FACADESLAM_KERNEL
#endif
