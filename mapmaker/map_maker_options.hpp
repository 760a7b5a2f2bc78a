#pragma once
// Every tunable of the map maker, with PTAM-like defaults. Loaded from the
// `mapmaker:` section of configs/slam.yaml.
#include <array>

#include "core/map/label_policy.hpp"
#include "mapmaker/ba/ba_selection.hpp"
#include "mapmaker/ba/bundle_adjuster.hpp"
#include "mapmaker/depth_prior_points.hpp"
#include "mapmaker/epipolar_partner.hpp"
#include "mapmaker/ground_gauge.hpp"
#include "mapmaker/keyframe_culling.hpp"

namespace facadeslam {

struct EpipolarSearchOptions {
  // New-point candidates per pyramid level of a new keyframe (strongest
  // FAST corners first, away from existing measurements).
  std::array<int, 4> max_candidates_per_level{{400, 200, 100, 50}};
  double min_distance_to_measurement = 4.0;  // level pixels
  double depth_range_sigmas = 3.0;           // search depth: mean +- this x sigma
  double min_depth_fraction = 0.25;          // ... but at least this x mean depth
  // ... and out to at least this x mean depth: a street's depths run from
  // the parked cars beside the camera to the houses at its end, far beyond
  // mean + 3 sigma, and those far points are the ones that stay in view
  // when driving forward (kitti00-300 ran out of map 15 frames after its
  // first turn without them: in view 650 -> 40 points). Only with a far
  // partner (EpipolarPartnerOptions::far_baseline): from the near one alone
  // the far points are too poorly triangulated (street-drive 0.02 -> 9.7 %).
  double min_far_depth_factor = 5.0;
  double max_line_distance = 1.5;     // corners within this of the epipolar line, level pixels
  float max_zmssd_per_pixel = 400.f;  // patch match bound (grey levels^2 per pixel)
  double max_reprojection_px = 2.0;   // level pixels, in both views after triangulation
  double min_parallax_deg = 0.5;      // rays must not be near parallel (x 2^level)
  // Warp each template into the other keyframe at the mean scene depth (on a
  // plane facing the new keyframe) instead of comparing same-level patches
  // unwarped: forward motion scales patches between keyframes.
  bool warp_templates = true;
  // Score every pixel along the epipolar segment, not only the other
  // keyframe's FAST corners near it (PTAM): a corner seen at another scale
  // is often not a FAST corner there.
  bool dense_line_search = true;
};

struct MapMakerOptions {
  EpipolarSearchOptions epipolar;
  // When the initial pair has at least this median parallax, both initial
  // keyframes' corners are searched at every level against the other one,
  // so the first map has coarse-level points (PTAM does it always). Below it
  // (street pans initialise at 1-2 degrees, usually by homography) the
  // coarse matches are too poorly triangulated: the demo's ATE went from
  // 3 % to 16 % of its path. Views around an object (templeRing: 16
  // degrees) need the coarse points to survive their large steps.
  double densify_initial_map_min_parallax_deg = 5.0;
  EpipolarPartnerOptions epipolar_partner;
  // Keyframes the tracker took because the camera turned near an existing
  // keyframe also get points at a prior depth (depth_prior_points.hpp).
  bool depth_prior_points = true;
  DepthPriorOptions depth_prior;
  LocalBaOptions local_ba_selection;
  BundleAdjusterOptions local_ba;
  BundleAdjusterOptions global_ba;
  // A point that the tracker searched for this often and found less than
  // this share of the time is removed (PTAM's outlier rule).
  int outlier_min_searches = 20;
  double outlier_max_found_ratio = 0.2;
  // Redundant keyframes are culled after each new one (keyframe_culling.hpp).
  KeyFrameCullingOptions culling;
  // The camera's height above the road holds the scale (ground_gauge.hpp).
  GroundGaugeOptions ground_gauge;
  // Synchronous mode: a global BA after every this many keyframes (the
  // threaded map maker runs it whenever it is idle instead).
  int sync_global_ba_every = 5;
  // The tracker searches for each point's patch as the newest keyframe that
  // measured it saw it (MapPoint::view), not as its source keyframe did.
  bool newest_view_templates = true;
  // Label-aware bundle adjustment (set from configs/semantics.yaml when
  // semantics are on): the measurements of points with these labels (things
  // that move, which the tracker leaves out too) are left out.
  LabelPolicy labels;  // left-out points (LabelPolicy::left_out); no classes: labels are ignored
};

}  // namespace facadeslam
