#pragma once
// The camera's height above the road as a gauge for the monocular scale.
//
// A camera mounted on a vehicle keeps its height above the road and the
// road's normal in the camera frame. Monocular SLAM cannot observe scale, and
// on driving video it drifts in the turns (kitti00-300: +9 % and +12 %), where
// each keyframe shares few points with the ones before it. The road under
// each keyframe measures that drift: the same road seen from a map whose
// scale grew 10 % lies 10 % further below the camera.
//
// How:
//  * the reference: the first keyframes' points below the camera, each in the
//    camera frame of a keyframe measuring it, pooled (with a rigid mount they
//    all lie on one plane in the camera frame) and fitted with a plane by
//    RANSAC (normal within max_tilt_deg of the camera's down axis). Its
//    normal and the camera's height above it, in map units, are the gauge.
//    The cameras must have moved as a vehicle's do: forward along the
//    optical axis, the plane's normal the same in the world from every
//    keyframe (turning about it only) and the camera centres at the same
//    height above it. Hand-held cameras (tilting,
//    raised and lowered) and cameras with no such plane get no gauge.
//  * per keyframe: the bundle adjustment's points (its own and its
//    neighbours': a keyframe alone sees few road corners) in the lane ahead
//    of it (the reference normal, fixed: a ground fitted per keyframe tilts
//    through parked cars and far points) whose heights below the camera
//    cluster within inlier_band of the expected height; the densest cluster
//    wins. Keyframes tilted from the reference are not held. The bundle adjustment
//    then holds those points at the reference height below the keyframe
//    with sigma (BaGroundObservation), robustly.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "mapmaker/ba/ba_problem.hpp"

namespace facadeslam {

struct GroundGaugeOptions {
  bool enabled = true;
  // The reference is fitted once the map has this many keyframes, and tried
  // again at each new keyframe up to max_reference_keyframes.
  std::size_t reference_keyframes = 4;
  std::size_t max_reference_keyframes = 20;
  double max_tilt_deg = 15.0;          // the ground normal from the camera's +y (down) axis
  double max_normal_spread_deg = 2.0;  // the normal in the world, between keyframes
  double max_height_spread = 0.05;     // x height: the camera centres' heights above the plane
  // ... and travelled within this of the optical axis (a forward-looking
  // camera on a vehicle; a walker looking about, a pan, does not).
  double max_motion_angle_deg = 10.0;
  // A keyframe whose ground normal in the world is further than this from
  // the reference keyframes' has tilted on its mount (a hand-held camera
  // looking up): it is not held.
  double max_keyframe_tilt_deg = 4.0;
  double reference_inlier_band = 0.02;     // x height: reference plane inliers
  std::size_t min_reference_inliers = 40;  // over all pooled keyframes
  // The lane: points ahead of (and just behind) the camera, beside its path (x height).
  double lane_half_width = 2.0;
  double max_ahead = 15.0;
  double max_behind = 5.0;  // the road under and behind the camera is still its road
  // Per keyframe: heights within +- search_window of the expected one (the
  // keyframe's last estimate, else the reference) are searched for the
  // densest cluster of width 2 x inlier_band.
  double search_window = 0.15;
  double inlier_band = 0.03;
  std::size_t min_inliers = 8;
  std::size_t max_points_per_keyframe = 40;
  // The keyframe height's standard deviation (x reference height), shared by
  // its ground points, each of which counts with point_sigma in the robust loss.
  double keyframe_sigma = 0.01;
  double point_sigma = 0.03;
};

struct GroundReference {
  Eigen::Vector3d normal_c{0, 1, 0};  // unit, pointing from the camera to the ground
  Eigen::Vector3d normal_w{0, 1, 0};  // the same in the world, from the first reference keyframe
  double height = 1.0;                // camera height above the ground, map units
  std::size_t inliers = 0;
};

// One keyframe's view for the reference: its pose and its measured points in
// its camera frame.
struct GroundView {
  SE3d T_c_w;
  std::vector<Eigen::Vector3d> points_c;
};

// The plane through the pooled camera-frame points, or none (no plane, or
// cameras that did not move like a vehicle's). Deterministic (a fixed-seed
// RANSAC).
std::optional<GroundReference> fit_ground_reference(const std::vector<GroundView>& views,
                                                    const GroundGaugeOptions& options);

struct GroundCluster {
  double height = 0.0;               // median height of the inliers, map units
  std::vector<std::size_t> inliers;  // indices into the points given
};

// The ground points among one keyframe's camera-frame points, searched around
// `expected_height`, or none (fewer than min_inliers).
std::optional<GroundCluster> find_ground(const std::vector<Eigen::Vector3d>& points_c, const GroundReference& reference,
                                         double expected_height, const GroundGaugeOptions& options);

class GroundGauge {
 public:
  explicit GroundGauge(GroundGaugeOptions options = {}) : options_(options) {}

  const GroundGaugeOptions& options() const { return options_; }
  const std::optional<GroundReference>& reference() const { return reference_; }

  // Tries to fit the reference when enabled, not yet fitted, and the map's
  // `keyframes` are between reference_keyframes and max_reference_keyframes
  // (once beyond, it stops trying). `views` (one per keyframe) is asked for
  // only then: building them transforms every measurement of the map.
  void try_reference(std::size_t keyframes, const std::function<std::vector<GroundView>()>& views);

  // Adds ground observations to `problem` for its keyframes (free ones only
  // unless `fixed_too`) whose ground is found; returns how many keyframes.
  std::size_t constrain(BaProblem& problem, bool fixed_too);

  // Heights found for the keyframes, map units (the newest last estimate).
  const std::map<std::uint64_t, double>& heights() const { return heights_; }

  void reset();

 private:
  GroundGaugeOptions options_;
  std::optional<GroundReference> reference_;
  bool gave_up_ = false;
  std::map<std::uint64_t, double> heights_;  // by keyframe id
};

}  // namespace facadeslam
