#pragma once
// Bilinear sampling of 8-bit images at arbitrary float positions, for the
// template warp. Internal to tracker/; callers guarantee that every sample
// and its right/lower neighbour lie inside the image.
#include <cstddef>
#include <cstdint>

namespace facadeslam::patch::detail {

// Value at (x, y) of the image whose row 0 starts at `data` with `step` bytes
// per row; requires 0 <= x < cols - 1 and 0 <= y < rows - 1.
// Truncation is the floor here because x, y >= 0 (and avoids a libm call
// on baseline x86-64, which has no SSE4.1 round instruction).
inline float bilinear(const std::uint8_t* data, std::size_t step, float x, float y) {
  const int ix = static_cast<int>(x), iy = static_cast<int>(y);
  const float ax = x - static_cast<float>(ix), ay = y - static_cast<float>(iy);
  const std::uint8_t* p = data + static_cast<std::size_t>(iy) * step + static_cast<std::size_t>(ix);
  const float top = p[0] + ax * (static_cast<float>(p[1]) - p[0]);
  const float bottom = p[step] + ax * (static_cast<float>(p[step + 1]) - p[step]);
  return top + ay * (bottom - top);
}

}  // namespace facadeslam::patch::detail
