#pragma once
// The plain description of a bundle adjustment problem: keyframe poses, map
// point positions and the measurements linking them. It deliberately knows
// nothing of the Map or its locks: the map maker copies the part of the map it
// wants to adjust into a BaProblem (under the map lock, briefly), solves it
// without any lock, and writes the adjusted poses and positions back.
//
// Gauge (monocular SLAM has 7 unobservable degrees of freedom: rotation,
// translation and scale of the whole map): the CALLER fixes at least one
// keyframe taking part (BundleAdjuster::solve rejects a problem with no fixed
// block). One fixed keyframe removes rotation and translation; the scale is
// removed too when
//  * a second fixed keyframe (local BA: the fixed neighbours) or fixed points
//    observe the free points, or
//  * `scale_anchor` keeps one free keyframe's camera centre at its current
//    distance from a fixed keyframe's centre (recommended for a global BA
//    whose only fixed keyframe is the first one: see bundle_adjuster.hpp).
// Without either, the scale direction is left to Levenberg–Marquardt's
// damping: it has zero gradient, so it moves little, but it is not pinned.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <vector>

#include <Eigen/Core>

#include "core/lie/se3.hpp"

namespace facadeslam {

struct BaKeyFrame {
  std::uint64_t id = 0;  // the caller's id, carried through untouched
  SE3d T_c_w;            // world -> camera
  bool fixed = false;    // constant during the solve
};

struct BaPoint {
  std::uint64_t id = 0;
  Eigen::Vector3d p_w{0, 0, 0};  // world position
  bool fixed = false;
};

struct BaObservation {
  std::size_t keyframe = 0;     // index into BaProblem::keyframes
  std::size_t point = 0;        // index into BaProblem::points
  Eigen::Vector2d pixel{0, 0};  // measured position in LEVEL-0 pixels
  int level = 0;                // pyramid level it was found at: sigma = 2^level px
  double weight = 1.0;          // its share of the cost (the loss times this), in (0, 1]
};

// Keeps |centre(keyframes[keyframe]) - centre(keyframes[reference])| at its
// value on entry to solve(): fixes the monocular scale with exactly one
// constraint (fixing a second keyframe outright would also freeze its
// rotation and direction, which are observable). `reference` must be fixed,
// `keyframe` free, and their centres apart.
struct BaScaleAnchor {
  std::size_t keyframe = 0;   // index into BaProblem::keyframes
  std::size_t reference = 0;  // index into BaProblem::keyframes
};

// A point on the ground under a keyframe: its height along the ground's
// normal in the keyframe's camera frame should be the camera's height above
// the ground (a camera mounted on a vehicle keeps it), which fixes the
// monocular scale locally (mapmaker/ground_gauge.hpp). Residual:
//   r = (normal_c . (T_c_w * p_w) - height) / sigma,  robust loss x weight.
struct BaGroundObservation {
  std::size_t keyframe = 0;           // index into BaProblem::keyframes
  std::size_t point = 0;              // index into BaProblem::points
  Eigen::Vector3d normal_c{0, 1, 0};  // unit, pointing down from the camera
  double height = 1.0;                // > 0, map units
  double sigma = 0.05;                // > 0, map units
  double weight = 1.0;                // > 0: its share of the keyframe's prior
};

struct BaProblem {
  std::vector<BaKeyFrame> keyframes;
  std::vector<BaPoint> points;
  std::vector<BaObservation> observations;
  std::vector<BaGroundObservation> ground;
  std::optional<BaScaleAnchor> scale_anchor;
};

// The largest pyramid level accepted in an observation (sigma = 2^level px).
inline constexpr int kMaxBaLevel = 15;

// Throws Error naming the first offending element unless: every observation
// indexes an existing keyframe and point, has a finite pixel, a level in
// [0, kMaxBaLevel] and a weight in (0, 1]; every pose and point is finite;
// every ground observation indexes an existing keyframe and point, has a
// unit normal and finite positive height, sigma and weight;
// and the scale anchor, if any, names two distinct keyframes, the reference
// fixed, the other free, with distinct centres.
void validate_ba_problem(const BaProblem& problem);

}  // namespace facadeslam
