#pragma once
// Every tunable of the tracker, with PTAM's values as defaults. Loaded from
// the `tracker:` section of configs/slam.yaml (slam/slam_options.hpp).
#include <cstdint>

#include "core/image/image_pyramid.hpp"
#include "core/map/label_policy.hpp"
#include "core/patch/patch_search.hpp"
#include "core/patch/patch_warp.hpp"
#include "tracker/pose_update.hpp"
#include "tracker/descriptor_relocaliser.hpp"
#include "tracker/relocaliser.hpp"

namespace facadeslam {

struct TrackerOptions {
  PyramidOptions pyramid;
  patch::TemplateOptions templates;
  // PTAM's patch bound is 500 and it searches FAST corners only; on real
  // street video at 10 Hz (KITTI) the patches change more between views:
  // a looser bound and, when no corner matches, every pixel within 3 of the
  // prediction (measured on the KITTI 06 snippet: docs/benchmarks.md).
  patch::SearchOptions search{.max_zmssd_per_pixel = 800.f, .dense_radius = 3};
  PoseUpdateOptions pose;
  RelocaliserOptions relocaliser;
  // When the small blurry image gives no pose that tracks well: ORB + PnP.
  DescriptorRelocaliserOptions descriptor_relocaliser;

  // Coarse stage: a few points found at the coarse levels, searched over a
  // wide radius, to survive fast motion. Radii are in level-0 pixels.
  bool coarse_stage = true;
  int coarse_min_level = 2;  // points searched at this level or above
  int coarse_max_points = 60;
  int coarse_min_found = 10;  // below this the coarse pose is not used
  double coarse_radius_px = 30.0;
  // When the fine stage fails from the coarse stage's pose, run it again
  // from the motion model's prediction and keep the better (Tracker::track).
  bool retry_from_prediction = true;
  // Fine stage: up to this many points over all levels, tight radius.
  int fine_max_points = 1000;
  double fine_radius_px = 8.0;  // without a coarse stage
  double fine_radius_after_coarse_px = 5.0;

  // Motion model: constant velocity, decayed (PTAM).
  double velocity_decay = 0.9;

  // Tracking quality = found / searched in the fine stage.
  double quality_good = 0.3;
  double quality_lost = 0.13;
  int min_found = 20;  // fewer points found is a failure whatever the ratio
  // This many inliers is good tracking whatever the ratio: around a 3D
  // object (templeRing) half of the projected points are occluded or seen
  // from too far round, so the ratio stays low while hundreds of points
  // still pin the pose down.
  int good_found = 150;
  // Inliers this far from their projections (RMS, level-0 pixels) are not
  // good tracking whatever their number: on a facade's repeated windows the
  // search can find the neighbouring corner for most points and the pose
  // settles between the two (measured: Strecha views 15 degrees apart
  // "tracked" at 5-7 px with the rotation half the true one; sharp video
  // tracks at 0.3-2.2 px: visp-cube, the demo, KITTI, templeRing).
  double max_good_rms_px = 3.0;
  // Bad frames in a row still tracked from the motion model before the
  // relocaliser takes over (PTAM's NUM_LOST_FRAMES).
  int lost_frames_before_relocalising = 3;
  // ... but the relocaliser is also tried at once on the first bad frame:
  // when the view jumped (a multi-view set, a dropped stretch of video) the
  // frames the motion model would spend are lost for nothing, and the
  // relocaliser only accepts a pose that tracks well, so a blurred frame
  // costs its time but no wrong pose.
  bool relocalise_on_first_bad_frame = true;

  // Keyframes: only when tracking is good, enough frames have passed, and no
  // keyframe sees the scene as the camera does now: every keyframe is either
  // far away relative to its scene depth (PTAM's rule) or looks in another
  // direction. The second half adds keyframes when the camera turns on the
  // spot, which PTAM never does: without them the map ends at the edge of
  // the last keyframe's view and tracking is lost once the camera has turned
  // past it.
  int keyframe_min_frames = 20;
  double keyframe_min_distance = 0.12;         // x the nearest keyframe's mean scene depth
  double keyframe_min_angle_deg = 15.0;        // between optical axes
  int keyframe_min_frames_turning = 10;        // turning is fast: the view leaves the map in a second
  double keyframe_distance_after_turn = 0.25;  // x keyframe_min_distance for the first keyframe after a turn
  // The keyframe queue's capacity (the System builds it): candidates the
  // map maker has not taken yet; while it is full the tracker asks for none.
  std::size_t keyframe_max_queue = 3;
  // ... and, whatever the distance, when the points found fall below this
  // share of the most found in a frame since the last keyframe (the view
  // leaves the map: forward motion at 10 Hz), at most every this many frames.
  double keyframe_min_overlap = 0.9;
  int keyframe_min_frames_overlap = 2;
  // ... except on a revisit: when a keyframe covers the view (near, looking
  // the same way) and the newest keyframe is far from the camera or was
  // made this many frames ago or more, the camera is on mapped ground; the
  // found count falling is then not the view leaving the map (a dense map's
  // points are searched up to a cap, and which are found varies), and a
  // keyframe there would only duplicate the old one: a looped replay grew
  // by 1.4 keyframes and 280 points per pass without this.
  bool keyframe_overlap_skips_revisits = true;
  int keyframe_revisit_age_frames = 60;

  // Label-aware tracking (core/map/label_policy.hpp): set from
  // configs/semantics.yaml when semantics are on; no classes: labels are ignored.
  LabelPolicy labels;

  std::uint64_t seed = 1;  // point-sampling order; fixed for reproducible runs
};

}  // namespace facadeslam
