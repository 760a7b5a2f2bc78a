#pragma once
// The 8x8 patch a map point is searched for with (PTAM), already warped into
// the current view at the pyramid level it will be searched at.
//
// Pixel layout: template pixel (col i, row j), i, j = 0..7, sits at the offset
// (i - 4, j - 4) SEARCH-LEVEL pixels from the point's projection, i.e. the
// point is at template pixel (4, 4) and the patch spans offsets -4..+3. This
// is PTAM's layout. A symmetric -3.5..+3.5 layout would put the point between
// pixels, so a candidate centred on an integer FAST corner would always sit
// half a pixel off; with integer offsets the candidate patch is exactly the
// 8x8 block of image pixels around the corner and no resampling is needed.
#include <array>
#include <cstdint>

#include <Eigen/Core>

namespace facadeslam::patch {

inline constexpr int kPatchSize = 8;
inline constexpr int kPatchPixels = kPatchSize * kPatchSize;
// Offset of template pixel 0 from the point, in search-level pixels.
inline constexpr int kPatchFirstOffset = -kPatchSize / 2;

// Why a template could not be made (kValid when it could).
enum class TemplateStatus : std::uint8_t {
  kValid,
  kBehindCamera,   // the point is not in front of the current camera
  kBadWarp,        // warp degenerate/mirrored, or its scale is outside the usable range
  kOutsideSource,  // the warped patch leaves the source keyframe's image
  kTextureless,    // too little intensity variance to match reliably
};

const char* to_string(TemplateStatus status);

struct PatchTemplate {
  // Zero-mean intensities (grey levels), row-major in the layout above.
  alignas(32) std::array<float, kPatchPixels> values{};
  // Intensity gradients of the template (grey levels per search-level pixel),
  // central differences on a 10x10 sampling, for sub-pixel refinement.
  alignas(32) std::array<float, kPatchPixels> grad_x{};
  alignas(32) std::array<float, kPatchPixels> grad_y{};

  // Affine warp A: level-0 pixels of the CURRENT image per pixel step at the
  // SOURCE keyframe's level (columns: one source-level pixel right, down).
  Eigen::Matrix2d warp = Eigen::Matrix2d::Zero();
  double warp_det = 0.0;               // det(A)
  int search_level = -1;               // pyramid level of the current image to search
  Eigen::Vector2d source_pixel{0, 0};  // patch centre at the source level (source-level pixels)
  // Source-level pixels per search-level pixel: (A / 2^search_level)^-1.
  Eigen::Matrix2d search_to_source = Eigen::Matrix2d::Zero();

  float mean = 0.f;  // mean of the sampled intensities before zero-meaning
  float ssq = 0.f;   // sum of squares of `values` (= 64 x variance)
  TemplateStatus status = TemplateStatus::kBadWarp;
  bool valid() const { return status == TemplateStatus::kValid; }
};

}  // namespace facadeslam::patch
