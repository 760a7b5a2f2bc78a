#include "core/patch/patch_search.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include <Eigen/LU>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace facadeslam::patch {
namespace {

constexpr int kFirst = kPatchFirstOffset;                  // -4
constexpr int kLast = kPatchFirstOffset + kPatchSize - 1;  // +3
constexpr float kInfinity = std::numeric_limits<float>::infinity();

// The inner kernels use SSE2 (baseline on x86-64) where available: GCC does
// not vectorise the 8-bit to float conversions by itself, and these loops
// are most of the tracker's per-point time. The portable fallbacks keep one
// accumulator per column so a compiler can vectorise them without -ffast-math.

// ZMSSD with a zero-mean template T, after scaling the candidate's contrast
// to the template's: with S_II = sum (I - mean I)^2, S_IT = sum I T and
// S_TT = sum T^2 (T is zero-mean, so sum (I - mean I) T = S_IT),
//   sum (g (I - mean I) - T)^2 = g^2 S_II - 2 g S_IT + S_TT,
// g = sqrt(S_TT / S_II) clamped to [1 / kMaxGain, kMaxGain]. Zero-meaning
// alone (PTAM) is blind to brightness offsets but not to gain: a cloud or
// exposure change of x1.8 multiplied the plain ZMSSD of every true match by
// up to 3, past the bound, and tracking was lost (synthetic street-lighting).
// The clamp keeps a flat candidate from being blown up into a match.
// Sums of I and I^2 of 8-bit pixels stay exact in float (< 2^24).
constexpr double kMaxGain = 2.0;

// g above, from S_II and S_TT.
double contrast_gain(double s_ii, double s_tt) {
  return s_ii > 0.0 ? std::clamp(std::sqrt(s_tt / s_ii), 1.0 / kMaxGain, kMaxGain) : 1.0;
}

float zmssd_from_sums(double si, double sii, double sit, float ssq) {
  const double s_ii = std::max(0.0, sii - si * si / kPatchPixels);
  const double gain = contrast_gain(s_ii, ssq);
  // Rounding can take an exact match a hair below zero.
  return std::max(0.f, static_cast<float>(gain * gain * s_ii - 2.0 * gain * sit + ssq));
}

#if defined(__SSE2__)
// The 8 pixels at p as two float vectors (columns 0-3, 4-7).
inline void load8(const std::uint8_t* p, __m128& lo, __m128& hi) {
  const __m128i zero = _mm_setzero_si128();
  const __m128i v16 = _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(p)), zero);
  lo = _mm_cvtepi32_ps(_mm_unpacklo_epi16(v16, zero));
  hi = _mm_cvtepi32_ps(_mm_unpackhi_epi16(v16, zero));
}

inline float horizontal_sum(__m128 v) {
  alignas(16) float f[4];
  _mm_store_ps(f, v);
  return (f[0] + f[1]) + (f[2] + f[3]);
}
#endif

float zmssd_block(const PatchTemplate& tpl, const std::uint8_t* top_left, std::size_t step) {
  const float* t = tpl.values.data();
#if defined(__SSE2__)
  __m128 s_i = _mm_setzero_ps(), s_ii = _mm_setzero_ps(), s_it = _mm_setzero_ps();
  for (int r = 0; r < kPatchSize; ++r, top_left += step, t += kPatchSize) {
    __m128 lo, hi;
    load8(top_left, lo, hi);
    s_i = _mm_add_ps(s_i, _mm_add_ps(lo, hi));
    s_ii = _mm_add_ps(s_ii, _mm_add_ps(_mm_mul_ps(lo, lo), _mm_mul_ps(hi, hi)));
    s_it = _mm_add_ps(s_it, _mm_add_ps(_mm_mul_ps(lo, _mm_load_ps(t)), _mm_mul_ps(hi, _mm_load_ps(t + 4))));
  }
  return zmssd_from_sums(horizontal_sum(s_i), horizontal_sum(s_ii), horizontal_sum(s_it), tpl.ssq);
#else
  float s_i[kPatchSize] = {}, s_ii[kPatchSize] = {}, s_it[kPatchSize] = {};
  for (int r = 0; r < kPatchSize; ++r, top_left += step, t += kPatchSize)
    for (int c = 0; c < kPatchSize; ++c) {
      const float v = top_left[c];
      s_i[c] += v;
      s_ii[c] += v * v;
      s_it[c] += v * t[c];
    }
  double si = 0, sii = 0, sit = 0;
  for (int c = 0; c < kPatchSize; ++c) {
    si += s_i[c];
    sii += s_ii[c];
    sit += s_it[c];
  }
  return zmssd_from_sums(si, sii, sit, tpl.ssq);
#endif
}

// Bilinear 8x8 block at integer base (ix, iy) and fractions (ax, ay) into out.
void sample_block(const cv::Mat& image, int ix, int iy, float ax, float ay, float* out) {
  const float w00 = (1 - ax) * (1 - ay), w01 = ax * (1 - ay), w10 = (1 - ax) * ay, w11 = ax * ay;
  const std::size_t step = image.step;
  const std::uint8_t* p0 = image.ptr<std::uint8_t>(iy + kFirst) + ix + kFirst;
#if defined(__SSE2__)
  // Each image row is converted once and used as the lower row of one
  // output row and the upper row of the next. Loads are 8 bytes at p and
  // p + 1, never past the block's last column (ix + 4).
  const __m128 v00 = _mm_set1_ps(w00), v01 = _mm_set1_ps(w01), v10 = _mm_set1_ps(w10), v11 = _mm_set1_ps(w11);
  __m128 a_lo, a_hi, a1_lo, a1_hi;
  load8(p0, a_lo, a_hi);
  load8(p0 + 1, a1_lo, a1_hi);
  for (int r = 0; r < kPatchSize; ++r, out += kPatchSize) {
    p0 += step;
    __m128 b_lo, b_hi, b1_lo, b1_hi;
    load8(p0, b_lo, b_hi);
    load8(p0 + 1, b1_lo, b1_hi);
    const __m128 top_lo = _mm_add_ps(_mm_mul_ps(v00, a_lo), _mm_mul_ps(v01, a1_lo));
    const __m128 top_hi = _mm_add_ps(_mm_mul_ps(v00, a_hi), _mm_mul_ps(v01, a1_hi));
    const __m128 bot_lo = _mm_add_ps(_mm_mul_ps(v10, b_lo), _mm_mul_ps(v11, b1_lo));
    const __m128 bot_hi = _mm_add_ps(_mm_mul_ps(v10, b_hi), _mm_mul_ps(v11, b1_hi));
    _mm_storeu_ps(out, _mm_add_ps(top_lo, bot_lo));
    _mm_storeu_ps(out + 4, _mm_add_ps(top_hi, bot_hi));
    a_lo = b_lo;
    a_hi = b_hi;
    a1_lo = b1_lo;
    a1_hi = b1_hi;
  }
#else
  for (int r = 0; r < kPatchSize; ++r, p0 += step, out += kPatchSize) {
    const std::uint8_t* p1 = p0 + step;
    for (int c = 0; c < kPatchSize; ++c) out[c] = w00 * p0[c] + w01 * p0[c + 1] + w10 * p1[c] + w11 * p1[c + 1];
  }
#endif
}

// The constant Gauss-Newton matrix of the sub-pixel parameters (dx, dy, b):
// sum of j j^T with j = (grad_x, grad_y, 1).
Eigen::Matrix3d gauss_newton_matrix(const PatchTemplate& tpl) {
  double sxx, sxy, syy, sx, sy;
#if defined(__SSE2__)
  __m128 vxx = _mm_setzero_ps(), vxy = _mm_setzero_ps(), vyy = _mm_setzero_ps(), vx = _mm_setzero_ps(),
         vy = _mm_setzero_ps();
  for (std::size_t k = 0; k < kPatchPixels; k += 4) {
    const __m128 gx = _mm_load_ps(&tpl.grad_x[k]), gy = _mm_load_ps(&tpl.grad_y[k]);
    vxx = _mm_add_ps(vxx, _mm_mul_ps(gx, gx));
    vxy = _mm_add_ps(vxy, _mm_mul_ps(gx, gy));
    vyy = _mm_add_ps(vyy, _mm_mul_ps(gy, gy));
    vx = _mm_add_ps(vx, gx);
    vy = _mm_add_ps(vy, gy);
  }
  sxx = horizontal_sum(vxx);
  sxy = horizontal_sum(vxy);
  syy = horizontal_sum(vyy);
  sx = horizontal_sum(vx);
  sy = horizontal_sum(vy);
#else
  sxx = sxy = syy = sx = sy = 0.0;
  for (std::size_t k = 0; k < kPatchPixels; ++k) {
    const double gx = tpl.grad_x[k], gy = tpl.grad_y[k];
    sxx += gx * gx;
    sxy += gx * gy;
    syy += gy * gy;
    sx += gx;
    sy += gy;
  }
#endif
  Eigen::Matrix3d H;
  H << sxx, sxy, sx, sxy, syy, sy, sx, sy, static_cast<double>(kPatchPixels);
  return H;
}

// floor() for |v| < kMaxCoordinate without a libm call (baseline x86-64 has
// no SSE4.1 rounding instruction); callers check the range first.
constexpr double kMaxCoordinate = 1e8;
inline int floor_to_int(double v) {
  const int i = static_cast<int>(v);  // truncates towards zero
  return i - (static_cast<double>(i) > v ? 1 : 0);
}

// Whether the bilinear 8x8 block around the integer base (ix, iy) is inside.
bool block_inside(const cv::Mat& image, int ix, int iy) {
  return ix + kFirst >= 0 && iy + kFirst >= 0 && ix + kLast + 1 <= image.cols - 1 && iy + kLast + 1 <= image.rows - 1;
}

}  // namespace

const char* to_string(SearchOutcome outcome) {
  switch (outcome) {
    case SearchOutcome::kFound: return "found";
    case SearchOutcome::kTemplateInvalid: return "template invalid";
    case SearchOutcome::kNoCandidate: return "no candidate";
    case SearchOutcome::kScoreTooHigh: return "score too high";
    case SearchOutcome::kSubpixelFailed: return "sub-pixel refinement failed";
  }
  return "unknown";
}

float zmssd_at(const PatchTemplate& tpl, const cv::Mat& image, int x, int y) {
  if (x + kFirst < 0 || y + kFirst < 0 || x + kLast >= image.cols || y + kLast >= image.rows) return kInfinity;
  return zmssd_block(tpl, image.ptr<std::uint8_t>(y + kFirst) + x + kFirst, image.step);
}

float zmssd_at_subpixel(const PatchTemplate& tpl, const cv::Mat& image, const Eigen::Vector2d& centre) {
  if (!(std::abs(centre.x()) < kMaxCoordinate && std::abs(centre.y()) < kMaxCoordinate)) return kInfinity;
  const int ix = floor_to_int(centre.x()), iy = floor_to_int(centre.y());
  if (!block_inside(image, ix, iy)) return kInfinity;
  float block[kPatchPixels];
  sample_block(image, ix, iy, static_cast<float>(centre.x() - ix), static_cast<float>(centre.y() - iy), block);
  double si = 0, sii = 0, sit = 0;
  for (int k = 0; k < kPatchPixels; ++k) {
    si += block[k];
    sii += static_cast<double>(block[k]) * block[k];
    sit += static_cast<double>(block[k]) * tpl.values[static_cast<std::size_t>(k)];
  }
  return zmssd_from_sums(si, sii, sit, tpl.ssq);
}

namespace {

// The contrast gain of a bilinearly sampled block against the template
// (contrast_gain), or exactly 1 within [1 / kMinSubpixelGain, kMinSubpixelGain]:
// bilinear resampling itself lowers a block's contrast by up to ~10 % at
// half-pixel offsets, so a small ratio is no evidence of a lighting change,
// and scaling by it biased the refined position by a few hundredths of a pixel.
constexpr double kMinSubpixelGain = 1.25;
double block_gain(const float* block, const PatchTemplate& tpl) {
  double si = 0, sii = 0;
  for (int k = 0; k < kPatchPixels; ++k) {
    si += block[k];
    sii += static_cast<double>(block[k]) * block[k];
  }
  const double gain = contrast_gain(std::max(0.0, sii - si * si / kPatchPixels), tpl.ssq);
  return (gain < kMinSubpixelGain && gain > 1.0 / kMinSubpixelGain) ? 1.0 : gain;
}

}  // namespace

SubpixelResult refine_subpixel(const PatchTemplate& tpl, const cv::Mat& image, const Eigen::Vector2d& start,
                               const SearchOptions& options) {
  SubpixelResult result;
  result.pixel = start;

  const Eigen::Matrix3d H = gauss_newton_matrix(tpl);
  Eigen::Matrix3d H_inv;
  bool invertible = false;
  H.computeInverseWithCheck(H_inv, invertible);
  if (!invertible) return result;

  double x = start.x(), y = start.y();
  float b = 0.f;
  // The image's contrast is matched to the template's (as the coarse match
  // does) from each iteration's block, not estimated as a fourth parameter:
  // in an 8x8 window a gain parameter couples with the shift and cost a third
  // more sub-pixel error on images without any gain change.
  float gain = 1.f;
  const float conv2 = options.subpixel_convergence * options.subpixel_convergence;
  const double max_shift2 = static_cast<double>(options.max_subpixel_shift) * options.max_subpixel_shift;
  float block[kPatchPixels];
  for (int it = 0; it < options.max_subpixel_iterations; ++it) {
    if (!(std::abs(x) < kMaxCoordinate && std::abs(y) < kMaxCoordinate)) return result;  // also NaN
    const int ix = floor_to_int(x), iy = floor_to_int(y);
    if (!block_inside(image, ix, iy)) return result;
    sample_block(image, ix, iy, static_cast<float>(x - ix), static_cast<float>(y - iy), block);
    gain = static_cast<float>(block_gain(block, tpl));
    for (float& v : block) v *= gain;
#if defined(__SSE2__)
    __m128 acc_x = _mm_setzero_ps(), acc_y = _mm_setzero_ps(), acc_b = _mm_setzero_ps();
    const __m128 vb = _mm_set1_ps(b);
    for (int k = 0; k < kPatchPixels; k += 4) {
      const std::size_t i = static_cast<std::size_t>(k);
      const __m128 e = _mm_sub_ps(_mm_sub_ps(_mm_loadu_ps(block + k), _mm_load_ps(&tpl.values[i])), vb);
      acc_x = _mm_add_ps(acc_x, _mm_mul_ps(_mm_load_ps(&tpl.grad_x[i]), e));
      acc_y = _mm_add_ps(acc_y, _mm_mul_ps(_mm_load_ps(&tpl.grad_y[i]), e));
      acc_b = _mm_add_ps(acc_b, e);
    }
    const Eigen::Vector3d g(horizontal_sum(acc_x), horizontal_sum(acc_y), horizontal_sum(acc_b));
#else
    float acc_x[kPatchSize] = {}, acc_y[kPatchSize] = {}, acc_b[kPatchSize] = {};
    for (int r = 0; r < kPatchSize; ++r)
      for (int c = 0; c < kPatchSize; ++c) {
        const std::size_t k = static_cast<std::size_t>(r * kPatchSize + c);
        const float e = block[k] - tpl.values[k] - b;
        acc_x[c] += tpl.grad_x[k] * e;
        acc_y[c] += tpl.grad_y[k] * e;
        acc_b[c] += e;
      }
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (int c = 0; c < kPatchSize; ++c) g += Eigen::Vector3d(acc_x[c], acc_y[c], acc_b[c]);
#endif
    const Eigen::Vector3d delta = H_inv * g;
    // Inverse composition: the template moved by +delta, so the image position by -delta.
    x -= delta.x();
    y -= delta.y();
    b += static_cast<float>(delta.z());
    result.iterations = it + 1;
    result.pixel = {x, y};
    result.brightness_offset = b / gain;
    result.gain = 1.f / gain;
    if ((result.pixel - start).squaredNorm() > max_shift2) return result;
    if (static_cast<float>(delta.head<2>().squaredNorm()) < conv2) {
      result.converged = std::abs(x) < kMaxCoordinate && std::abs(y) < kMaxCoordinate &&
                         block_inside(image, floor_to_int(x), floor_to_int(y));
      return result;
    }
  }
  return result;
}

namespace {

// The search proper, for any source of "the corners of row y" (called with
// increasing y).
template <class RowCorners>
PatchSearchResult search_rows(const PatchTemplate& tpl, const ImagePyramid& pyramid,
                              const Eigen::Vector2d& predicted_level0, double radius, const SearchOptions& options,
                              RowCorners&& row_corners) {
  PatchSearchResult result;
  if (!tpl.valid()) {
    result.outcome = SearchOutcome::kTemplateInvalid;
    return result;
  }
  const int level = tpl.search_level;
  result.level = level;
  const cv::Mat& image = pyramid.level(level).image;
  const Eigen::Vector2d p = ImagePyramid::level0_to_level(predicted_level0, level);
  if (!(radius >= 0.0) || !p.allFinite()) {
    result.outcome = SearchOutcome::kNoCandidate;
    return result;
  }

  // The search square, cut to where a candidate leaves room for the bilinear
  // block of the refinement; per row, the first column by binary search,
  // then the circle test.
  const double r2 = radius * radius;
  const int x_lo = static_cast<int>(std::max<double>(-kFirst, std::ceil(p.x() - radius)));
  const int y_lo = static_cast<int>(std::max<double>(-kFirst, std::ceil(p.y() - radius)));
  const int x_hi = static_cast<int>(std::min<double>(image.cols - 2 - kLast, std::floor(p.x() + radius)));
  const int y_hi = static_cast<int>(std::min<double>(image.rows - 2 - kLast, std::floor(p.y() + radius)));
  const std::uint8_t* data = image.ptr<std::uint8_t>(0);
  const std::size_t step = image.step;
  float best = kInfinity;
  const Corner* best_corner = nullptr;
  for (int y = y_lo; y <= y_hi; ++y) {
    const std::span<const Corner> row = row_corners(y);
    const double dy = y - p.y();
    const double room = r2 - dy * dy;
    const std::uint8_t* top = data + static_cast<std::size_t>(y + kFirst) * step;
    for (auto it = std::lower_bound(row.begin(), row.end(), x_lo, [](const Corner&c, int x) { return c.x < x; });
         it != row.end() && it->x <= x_hi; ++it) {
      const double dx = it->x - p.x();
      if (dx * dx > room) continue;
      ++result.candidates;
      const float score = zmssd_block(tpl, top + (it->x + kFirst), step);
      if (score < best) {
        best = score;
        best_corner = &*it;
      }
    }
  }
  Eigen::Vector2i best_pixel = best_corner ? Eigen::Vector2i(best_corner->x, best_corner->y) : Eigen::Vector2i(-1, -1);
  const float bound = options.max_zmssd_per_pixel * kPatchPixels;
  if (options.dense_radius > 0 && (!best_corner || best > bound)) {
    // No FAST corner matches: every pixel near the prediction. Under strong
    // scale change or oblique views the point's corner is often not a FAST
    // corner in this frame, while a good motion model puts it within a few
    // pixels of the prediction.
    const double dense = std::min(radius, static_cast<double>(options.dense_radius));
    const int dx_lo = std::max(x_lo, static_cast<int>(std::ceil(p.x() - dense)));
    const int dx_hi = std::min(x_hi, static_cast<int>(std::floor(p.x() + dense)));
    const int dy_lo = std::max(y_lo, static_cast<int>(std::ceil(p.y() - dense)));
    const int dy_hi = std::min(y_hi, static_cast<int>(std::floor(p.y() + dense)));
    for (int y = dy_lo; y <= dy_hi; ++y) {
      const std::uint8_t* top = data + static_cast<std::size_t>(y + kFirst) * step;
      for (int x = dx_lo; x <= dx_hi; ++x) {
        ++result.candidates;
        const float score = zmssd_block(tpl, top + (x + kFirst), step);
        if (score < best) {
          best = score;
          best_pixel = {x, y};
        }
      }
    }
  }
  if (best_pixel.x() < 0) {
    result.outcome = SearchOutcome::kNoCandidate;
    return result;
  }
  result.corner = best_pixel;
  result.zmssd = best;
  result.pixel_level = result.corner.cast<double>();
  if (best > bound) {
    result.outcome = SearchOutcome::kScoreTooHigh;
    return result;
  }
  if (options.subpixel) {
    const SubpixelResult refined = refine_subpixel(tpl, image, result.pixel_level, options);
    result.subpixel_iterations = refined.iterations;
    if (!refined.converged) {
      result.outcome = SearchOutcome::kSubpixelFailed;
      return result;
    }
    result.pixel_level = refined.pixel;
  }
  result.pixel_level0 = ImagePyramid::level_to_level0(result.pixel_level, level);
  result.outcome = SearchOutcome::kFound;
  return result;
}

}  // namespace

PatchSearchResult search_patch(const PatchTemplate& tpl, const SearchImage& frame,
                               const Eigen::Vector2d& predicted_level0, double radius, const SearchOptions& options) {
  const int level = tpl.search_level;
  return search_rows(tpl, frame.pyramid(), predicted_level0, radius, options,
                     [&](int y) { return frame.row(level, y); });
}

PatchSearchResult search_patch(const PatchTemplate& tpl, const ImagePyramid& pyramid,
                               const Eigen::Vector2d& predicted_level0, double radius, const SearchOptions& options) {
  // Without the row index: one binary search to the first row, then a cursor
  // that walks the sorted corners row by row.
  if (!tpl.valid())
    return search_rows(tpl, pyramid, predicted_level0, radius, options, [](int) { return std::span<const Corner>(); });
  const std::vector<Corner>& corners = pyramid.level(tpl.search_level).corners;
  auto cursor = corners.begin();
  bool started = false;
  return search_rows(tpl, pyramid, predicted_level0, radius, options, [&](int y) {
    if (!started) {
      cursor = std::lower_bound(corners.begin(), corners.end(), y, [](const Corner& c, int v) { return c.y < v; });
      started = true;
    }
    while (cursor != corners.end() && cursor->y < y) ++cursor;
    auto end = cursor;
    while (end != corners.end() && end->y == y) ++end;
    const std::span<const Corner> row(cursor, end);
    cursor = end;
    return row;
  });
}

}  // namespace facadeslam::patch
