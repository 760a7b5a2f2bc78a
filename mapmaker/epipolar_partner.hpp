#pragma once
// Which keyframe a new keyframe searches for new points against.
//
// PTAM takes the nearest keyframe. That fails when the camera turns on the
// spot: the nearest keyframe then stands where the new one stands, no ray
// pair has parallax, and the new view gets no points, so tracking runs out
// of map while the camera pans away. The partner must instead have
//  - a baseline of at least `min_baseline` x the new keyframe's scene depth
//    (parallax), and
//  - an optical axis within `max_axis_angle_deg` of the new one (the two
//    views share part of the scene and see patches at similar angles);
// among such keyframes the nearest wins (PTAM's choice when it works). If no
// keyframe qualifies, the nearest keyframe with the baseline, then plain
// nearest, is the fallback.
#include <cstddef>
#include <optional>
#include <vector>

#include "core/lie/se3.hpp"

namespace facadeslam {

struct EpipolarPartnerOptions {
  double min_baseline = 0.02;  // x the new keyframe's mean scene depth
  double max_axis_angle_deg = 45.0;
  // A second partner at least this far away (x the mean scene depth; 0:
  // none). Moving forward, the near partner leaves the points ahead, which
  // stay in view longest, without the parallax to triangulate them.
  // kitti00-300 tracks all its frames with 0.15-0.3 (ATE 1.02-1.25 %).
  double far_baseline = 0.2;
  // ... only when the camera moves forward: its motion from the near partner
  // within this angle of its optical axis (a car's camera: within a few
  // degrees, in turns too). Moving sideways or obliquely (a pan, a walk
  // looking 25 degrees off its path) the near partner gives the points
  // parallax already, and the far ones found through a second partner cost
  // accuracy: with 45 degrees street-walk's label accuracy fell to 0.69 and
  // street-traffic's and street-dynamic's ATE bars were missed; with 15 the
  // walks 20-25 degrees off their axis still got a far partner now and then.
  // kitti00-300 and street-suburb track the same with 10 as with 45.
  double far_max_motion_angle_deg = 10.0;
};

// Whether the camera at T_new_w, having come from T_near_w, moves forward
// within options.far_max_motion_angle_deg of its optical axis.
bool moving_forward(const SE3d& T_new_w, const SE3d& T_near_w, const EpipolarPartnerOptions& options);

// Index into `others` (their T_c_w), or nothing when `others` is empty.
std::optional<std::size_t> choose_epipolar_partner(const SE3d& T_new_w, double new_mean_depth,
                                                   const std::vector<SE3d>& others,
                                                   const EpipolarPartnerOptions& options);

// The far partner: the nearest keyframe sharing the view whose baseline is at
// least `far_baseline` x the new keyframe's scene depth, other than `near`;
// nothing when there is none or far_baseline is 0.
std::optional<std::size_t> choose_far_epipolar_partner(const SE3d& T_new_w, double new_mean_depth,
                                                       const std::vector<SE3d>& others, std::optional<std::size_t> near,
                                                       const EpipolarPartnerOptions& options);

}  // namespace facadeslam
