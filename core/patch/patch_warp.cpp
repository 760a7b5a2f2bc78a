#include "core/patch/patch_warp.hpp"

#include <algorithm>
#include <cstring>

#include "core/util/error.hpp"
#include "core/patch/bilinear.hpp"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace facadeslam::patch {
namespace {

// The template is sampled on a 10x10 grid (offsets -5..+4): the inner 8x8 are
// the values, the one-pixel ring feeds the central-difference gradients.
constexpr int kGrid = kPatchSize + 2;
constexpr int kGridFirst = kPatchFirstOffset - 1;
constexpr int kGridPixels = kGrid * kGrid;  // 100, a multiple of 4

// The grid's offsets flattened row-major, so it can be sampled 4 at a time.
struct GridOffsets {
  alignas(16) float dx[kGridPixels];
  alignas(16) float dy[kGridPixels];
};
constexpr GridOffsets make_grid_offsets() {
  GridOffsets g{};
  for (int k = 0; k < kGridPixels; ++k) {
    g.dx[k] = static_cast<float>(kGridFirst + k % kGrid);
    g.dy[k] = static_cast<float>(kGridFirst + k / kGrid);
  }
  return g;
}
constexpr GridOffsets kGridOffsets = make_grid_offsets();

// Bilinear samples of `image` at c + M d for every grid offset d; the caller
// has checked that the grid is inside. SSE2 does the arithmetic 4 samples at
// a time; the reads stay scalar (SSE2 has no gather) but take each pixel pair
// as one 16-bit load. Pixel offsets are computed in float, exact while the
// image holds fewer than 2^24 bytes (else the scalar path runs).
void sample_grid(const cv::Mat& image, float cx, float cy, float m00, float m01, float m10, float m11, float* out) {
  const std::uint8_t* data = image.ptr<std::uint8_t>(0);
  const std::size_t step = image.step;
#if defined(__SSE2__)
  if (step * static_cast<std::size_t>(image.rows) < (std::size_t{1} << 24)) {
    const __m128 vcx = _mm_set1_ps(cx), vcy = _mm_set1_ps(cy), vstep = _mm_set1_ps(static_cast<float>(step));
    const __m128 v00 = _mm_set1_ps(m00), v01 = _mm_set1_ps(m01), v10 = _mm_set1_ps(m10), v11 = _mm_set1_ps(m11);
    const __m128i low16 = _mm_set1_epi32(0xffff);
    alignas(16) std::int32_t offset[4];
    alignas(16) std::uint16_t top[4], bottom[4];
    for (int k = 0; k < kGridPixels; k += 4) {
      const __m128 dx = _mm_load_ps(kGridOffsets.dx + k), dy = _mm_load_ps(kGridOffsets.dy + k);
      const __m128 x = _mm_add_ps(vcx, _mm_add_ps(_mm_mul_ps(v00, dx), _mm_mul_ps(v01, dy)));
      const __m128 y = _mm_add_ps(vcy, _mm_add_ps(_mm_mul_ps(v10, dx), _mm_mul_ps(v11, dy)));
      // Truncation is the floor: x, y >= 0.
      const __m128 fx = _mm_cvtepi32_ps(_mm_cvttps_epi32(x)), fy = _mm_cvtepi32_ps(_mm_cvttps_epi32(y));
      const __m128 ax = _mm_sub_ps(x, fx), ay = _mm_sub_ps(y, fy);
      _mm_store_si128(reinterpret_cast<__m128i*>(offset), _mm_cvttps_epi32(_mm_add_ps(_mm_mul_ps(fy, vstep), fx)));
      for (int l = 0; l < 4; ++l) {
        const std::uint8_t* p = data + offset[l];
        std::memcpy(&top[l], p, 2);
        std::memcpy(&bottom[l], p + step, 2);
      }
      // Each 32-bit lane holds (left | right << 8); widen and split.
      const __m128i zero = _mm_setzero_si128();
      const __m128i t = _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(top)), zero);
      const __m128i u = _mm_unpacklo_epi8(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(bottom)), zero);
      const __m128 a = _mm_cvtepi32_ps(_mm_and_si128(t, low16)), b = _mm_cvtepi32_ps(_mm_srli_epi32(t, 16));
      const __m128 c = _mm_cvtepi32_ps(_mm_and_si128(u, low16)), d = _mm_cvtepi32_ps(_mm_srli_epi32(u, 16));
      const __m128 upper = _mm_add_ps(a, _mm_mul_ps(ax, _mm_sub_ps(b, a)));
      const __m128 lower = _mm_add_ps(c, _mm_mul_ps(ax, _mm_sub_ps(d, c)));
      _mm_storeu_ps(out + k, _mm_add_ps(upper, _mm_mul_ps(ay, _mm_sub_ps(lower, upper))));
    }
    return;
  }
#endif
  for (int k = 0; k < kGridPixels; ++k) {
    const float dx = kGridOffsets.dx[k], dy = kGridOffsets.dy[k];
    out[k] = detail::bilinear(data, step, cx + m00 * dx + m01 * dy, cy + m10 * dx + m11 * dy);
  }
}

// Template values (zero-mean), their gradients and sum of squares from the
// 10x10 grid; returns the mean.
float fill_template(const float (&grid)[kGrid][kGrid], PatchTemplate& t) {
  float sum = 0.f;
  for (int j = 1; j <= kPatchSize; ++j)
    for (int i = 1; i <= kPatchSize; ++i) sum += grid[j][i];
  const float mean = sum / kPatchPixels;
#if defined(__SSE2__)
  const __m128 vmean = _mm_set1_ps(mean), half = _mm_set1_ps(0.5f);
  __m128 vssq = _mm_setzero_ps();
  for (int j = 0; j < kPatchSize; ++j)
    for (int i = 0; i < kPatchSize; i += 4) {
      const float* c = &grid[j + 1][i + 1];
      const std::size_t k = static_cast<std::size_t>(j * kPatchSize + i);
      const __m128 v = _mm_sub_ps(_mm_loadu_ps(c), vmean);
      _mm_store_ps(&t.values[k], v);
      vssq = _mm_add_ps(vssq, _mm_mul_ps(v, v));
      _mm_store_ps(&t.grad_x[k], _mm_mul_ps(half, _mm_sub_ps(_mm_loadu_ps(c + 1), _mm_loadu_ps(c - 1))));
      _mm_store_ps(&t.grad_y[k], _mm_mul_ps(half, _mm_sub_ps(_mm_loadu_ps(c + kGrid), _mm_loadu_ps(c - kGrid))));
    }
  alignas(16) float s[4];
  _mm_store_ps(s, vssq);
  t.ssq = (s[0] + s[1]) + (s[2] + s[3]);
#else
  float ssq = 0.f;
  for (int j = 0; j < kPatchSize; ++j)
    for (int i = 0; i < kPatchSize; ++i) {
      const std::size_t k = static_cast<std::size_t>(j * kPatchSize + i);
      const float v = grid[j + 1][i + 1] - mean;
      t.values[k] = v;
      ssq += v * v;
      t.grad_x[k] = 0.5f * (grid[j + 1][i + 2] - grid[j + 1][i]);
      t.grad_y[k] = 0.5f * (grid[j + 2][i + 1] - grid[j][i + 1]);
    }
  t.ssq = ssq;
#endif
  return mean;
}

}  // namespace

const char* to_string(TemplateStatus status) {
  switch (status) {
    case TemplateStatus::kValid: return "valid";
    case TemplateStatus::kBehindCamera: return "behind camera";
    case TemplateStatus::kBadWarp: return "bad warp";
    case TemplateStatus::kOutsideSource: return "outside source image";
    case TemplateStatus::kTextureless: return "textureless";
  }
  return "unknown";
}

Eigen::Matrix2d patch_warp(const Eigen::Vector3d& p_c, const Eigen::Matrix3d& R_c_w, const PointGeometry& geometry,
                           const Camera& camera) {
  const Eigen::Matrix<double, 2, 3> J = camera.project_jacobian(p_c);
  Eigen::Matrix2d A;
  A.col(0) = J * (R_c_w * geometry.right_w);
  A.col(1) = J * (R_c_w * geometry.down_w);
  return A;
}

int choose_search_level(double warp_det, const TemplateOptions& options) {
  if (!(warp_det > 0.0)) return -1;  // mirrored, degenerate or NaN
  const int max_level = std::clamp(options.max_search_level, 0, kPyramidLevels - 1);
  int level = 0;
  double det = warp_det;
  while (level < max_level && det >= 2.0) {
    ++level;
    det *= 0.25;
  }
  if (det < options.min_search_det || det > options.max_search_det) return -1;
  return level;
}

PatchTemplate make_patch_template(const PatchSource& source, const Eigen::Matrix2d& warp,
                                  const TemplateOptions& options) {
  return make_patch_template_at_level(source, warp, choose_search_level(warp.determinant(), options), options);
}

PatchTemplate make_patch_template_at_level(const PatchSource& source, const Eigen::Matrix2d& warp, int search_level,
                                           const TemplateOptions& options) {
  if (!source.pyramid) throw Error("make_patch_template: the map point's source pyramid is missing");
  PatchTemplate t;
  t.warp = warp;
  t.warp_det = warp.determinant();
  t.search_level = search_level;
  if (t.search_level < 0 || t.search_level >= kPyramidLevels) {
    t.status = TemplateStatus::kBadWarp;
    return t;
  }
  t.search_to_source = warp.inverse() * ImagePyramid::level_scale(t.search_level);
  t.source_pixel = ImagePyramid::level0_to_level(source.pixel_level0, source.level);

  const cv::Mat& image = source.pyramid->level(source.level).image;
  const float cx = static_cast<float>(t.source_pixel.x()), cy = static_cast<float>(t.source_pixel.y());
  const float m00 = static_cast<float>(t.search_to_source(0, 0)), m01 = static_cast<float>(t.search_to_source(0, 1));
  const float m10 = static_cast<float>(t.search_to_source(1, 0)), m11 = static_cast<float>(t.search_to_source(1, 1));

  // The grid is an affine image of a square, so it is inside the image when
  // its four corners are (bilinear sampling needs x < cols - 1, y < rows - 1;
  // the margin absorbs float rounding differences between here and the
  // sampler).
  constexpr float kMargin = 1e-3f;
  const float max_x = static_cast<float>(image.cols - 1) - kMargin;
  const float max_y = static_cast<float>(image.rows - 1) - kMargin;
  constexpr float lo = static_cast<float>(kGridFirst), hi = static_cast<float>(kGridFirst + kGrid - 1);
  for (const float dx : {lo, hi})
    for (const float dy : {lo, hi}) {
      const float x = cx + (m00 * dx + m01 * dy), y = cy + (m10 * dx + m11 * dy);
      if (!(x >= 0.f && y >= 0.f && x < max_x && y < max_y)) {
        t.status = TemplateStatus::kOutsideSource;
        return t;
      }
    }

  alignas(16) float grid[kGrid][kGrid];
  sample_grid(image, cx, cy, m00, m01, m10, m11, &grid[0][0]);

  t.mean = fill_template(grid, t);
  t.status = t.ssq < options.min_variance * kPatchPixels ? TemplateStatus::kTextureless : TemplateStatus::kValid;
  return t;
}

PatchTemplate make_patch_template(const PatchSource& source, const PointGeometry& geometry, const SE3d& T_c_w,
                                  const Camera& camera, const TemplateOptions& options) {
  const Eigen::Matrix3d R_c_w = T_c_w.rotation_matrix();
  const Eigen::Vector3d p_c = R_c_w * geometry.p_w + T_c_w.translation();
  if (!(p_c.z() > 0.0)) {
    PatchTemplate t;
    t.status = TemplateStatus::kBehindCamera;
    return t;
  }
  return make_patch_template(source, patch_warp(p_c, R_c_w, geometry, camera), options);
}

}  // namespace facadeslam::patch
