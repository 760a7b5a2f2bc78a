#pragma once
// Warping a map point's source patch into the current view (PTAM's
// PatchFinder::CalcSearchLevelAndWarpMatrix + MakeTemplateCoarse).
//
// 1. Warp. The point's geometry stores right_w / down_w, the world offsets of
//    one SOURCE-LEVEL pixel step at the point. Their images under the current
//    pose and camera, linearised at the point (as PTAM does), are the columns
//    of the 2x2 warp
//        A = J_proj(p_c) * R_c_w * [right_w, down_w]
//    in LEVEL-0 pixels of the current image per source-level pixel.
//
// 2. Search level. A pixel step at current level l is 2^l level-0 pixels, so
//    the warp into level l is A_l = A / 2^l, whose determinant det(A) / 4^l is
//    the area one source-level pixel covers at level l. The template is best
//    conditioned where that area is closest to 1 (no strong magnification,
//    which blurs, and no strong minification, which aliases the bilinear
//    samples). In the log domain that is
//        l = clamp(round(log4 det(A)), 0, 3),
//    computed without logs as: start at l = 0 and step up while
//    det(A) / 4^l >= 2 (round switches level at 4^l * 2 = 4^(l + 1/2)).
//    PTAM switches at 3 instead of 2 (bias to the finer level); the rule here
//    is symmetric in log scale, as the project's design asks.
//    After clamping, det(A) / 4^l must lie in [min_search_det, max_search_det]
//    (default [1/4, 4]: a linear scale change of at most 2 left to the
//    template), else the template is rejected (kBadWarp) — PTAM's bound too.
//
// 3. Template. Search-level pixel offsets d (layout in patch_template.hpp)
//    map to source-level positions  s = c_src + (A / 2^l)^-1 d,  sampled
//    bilinearly in the source keyframe's level image. The samples are
//    zero-meaned; a variance below min_variance makes the template
//    kTextureless.
#include <Eigen/Core>

#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"
#include "core/map/map_point.hpp"
#include "core/patch/patch_template.hpp"

namespace facadeslam::patch {

struct TemplateOptions {
  int max_search_level = 3;      // highest current-image level to search (<= 3)
  double min_search_det = 0.25;  // accepted det(A) / 4^l range after level choice
  double max_search_det = 4.0;
  float min_variance = 16.f;  // grey levels^2 per pixel (std dev 4)
};

// A = J_proj(p_c) R_c_w [right_w, down_w]; p_c is the point in the current
// camera frame (z > 0), R_c_w the current rotation.
Eigen::Matrix2d patch_warp(const Eigen::Vector3d& p_c, const Eigen::Matrix3d& R_c_w, const PointGeometry& geometry,
                           const Camera& camera);

// The search level for a warp determinant (rule above); -1 when det <= 0 or
// det(A) / 4^l falls outside [min_search_det, max_search_det].
int choose_search_level(double warp_det, const TemplateOptions& options = {});

// Builds the template from an already known warp (p_c and A computed by the
// caller). `source.pyramid` must be set.
PatchTemplate make_patch_template(const PatchSource& source, const Eigen::Matrix2d& warp,
                                  const TemplateOptions& options = {});

// The same when the caller already chose the search level with
// choose_search_level(warp.determinant(), options) (the tracker does, to pick
// its coarse-stage points): the rule is applied once. A negative level gives
// a kBadWarp template.
// (A distinct name, not an overload: `make_patch_template(source, warp, {})`
// must keep meaning default options, not level 0.)
PatchTemplate make_patch_template_at_level(const PatchSource& source, const Eigen::Matrix2d& warp, int search_level,
                                           const TemplateOptions& options = {});

// Everything from the point, the current pose and the current (level-0) camera.
PatchTemplate make_patch_template(const PatchSource& source, const PointGeometry& geometry, const SE3d& T_c_w,
                                  const Camera& camera, const TemplateOptions& options = {});

}  // namespace facadeslam::patch
