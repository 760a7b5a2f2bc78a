#pragma once
// Finding a warped template in the current image (PTAM's
// PatchFinder::FindPatchCoarse + IterateSubPixToConvergence).
//
// Coarse: every FAST corner of the search level within `radius` of the
// prediction is scored by the zero-mean SSD between the template and the 8x8
// image block around the corner (layout: patch_template.hpp); the best one is
// accepted when its ZMSSD is at most 64 * max_zmssd_per_pixel. PTAM's bound is
// 500 grey levels^2 per pixel (an RMS difference of ~22 grey levels after
// removing the mean); zero-meaning makes it blind to brightness offsets, and
// the candidate's contrast is scaled to the template's (gain within x2 either
// way) before comparing, so that exposure and cloud changes are tolerated.
//
// Fine: inverse-compositional Lucas-Kanade on translation plus a brightness
// offset, g I(c + d) ~ T(d) + b, starting from the corner, the contrast gain g
// taken from each iteration's block as in the coarse match (1 unless the
// contrast differs by more than 25 %). The template's
// gradients make the 3x3 Gauss-Newton matrix constant, so each iteration is
// one bilinear pass over the 8x8 image block. It stops when the step is below
// `subpixel_convergence` search-level pixels; not converging within
// `max_subpixel_iterations` counts as not found (as in PTAM), and so do
// leaving the image or drifting more than `max_subpixel_shift` from the
// corner (guards PTAM lacks).
//
// Units: the radius and every sub-pixel tolerance are in SEARCH-LEVEL pixels
// (the template's search_level); the prediction and the returned position
// are level-0 pixels. A radius of R level-0 pixels is R / 2^search_level.
// Searching allocates nothing (given a SearchImage built once per frame).
#include <cstdint>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/image/image_pyramid.hpp"
#include "core/patch/patch_template.hpp"
#include "core/patch/search_image.hpp"

namespace facadeslam::patch {

struct SearchOptions {
  float max_zmssd_per_pixel = 500.f;   // PTAM's bound; accept ZMSSD <= 64 x this
  bool subpixel = true;                // refine the best corner to sub-pixel
  int max_subpixel_iterations = 10;    // PTAM: 10
  float subpixel_convergence = 0.03f;  // step length that counts as converged (PTAM: 0.03)
  float max_subpixel_shift = 2.f;      // farthest the refinement may move from the corner
  // When no FAST corner within the radius matches, every pixel within this
  // many search-level pixels of the prediction is scored (0: off, PTAM).
  int dense_radius = 0;
};

enum class SearchOutcome : std::uint8_t {
  kFound,
  kTemplateInvalid,  // the template was not valid (see TemplateStatus)
  kNoCandidate,      // no FAST corner within the radius (with the patch inside the image)
  kScoreTooHigh,     // the best corner's ZMSSD exceeds the bound
  kSubpixelFailed,   // sub-pixel refinement did not converge
};

const char* to_string(SearchOutcome outcome);

struct PatchSearchResult {
  SearchOutcome outcome = SearchOutcome::kNoCandidate;
  bool found() const { return outcome == SearchOutcome::kFound; }
  int level = -1;                      // search level
  Eigen::Vector2d pixel_level0{0, 0};  // found position, level-0 pixels
  Eigen::Vector2d pixel_level{0, 0};   // the same at the search level
  Eigen::Vector2i corner{0, 0};        // best corner, search-level pixels
  float zmssd = 0.f;                   // ZMSSD at the best corner
  int candidates = 0;                  // corners scored
  int subpixel_iterations = 0;
};

// ZMSSD of the template against the 8x8 block of `image` (8-bit grey) whose
// pixel (4, 4) is (x, y); +infinity when the block is not inside the image.
float zmssd_at(const PatchTemplate& tpl, const cv::Mat& image, int x, int y);

// The same at a sub-pixel position, the image sampled bilinearly.
float zmssd_at_subpixel(const PatchTemplate& tpl, const cv::Mat& image, const Eigen::Vector2d& centre);

struct SubpixelResult {
  bool converged = false;
  Eigen::Vector2d pixel{0, 0};    // refined position, pixels of `image`
  float brightness_offset = 0.f;  // the image block's mean (grey levels)
  float gain = 1.f;               // the image block's contrast over the template's
  int iterations = 0;
};

// Refines a position in `image` (the search-level image) from `start`.
SubpixelResult refine_subpixel(const PatchTemplate& tpl, const cv::Mat& image, const Eigen::Vector2d& start,
                               const SearchOptions& options = {});

// The whole search: corners of pyramid level tpl.search_level within
// `radius` search-level pixels of `predicted_level0`. Build the SearchImage
// once per frame and reuse it for every point.
PatchSearchResult search_patch(const PatchTemplate& tpl, const SearchImage& frame,
                               const Eigen::Vector2d& predicted_level0, double radius,
                               const SearchOptions& options = {});

// The same without the per-frame row index: a binary search to the first
// row, then a walk over every corner of the window's rows (slower when rows
// hold many corners; allocates nothing either).
PatchSearchResult search_patch(const PatchTemplate& tpl, const ImagePyramid& pyramid,
                               const Eigen::Vector2d& predicted_level0, double radius,
                               const SearchOptions& options = {});

}  // namespace facadeslam::patch
