#pragma once
// Where a keyframe may get new points (PTAM's ThinCandidates), shared by the
// epipolar search and the depth-prior points: its FAST corners at one
// pyramid level, strongest first, kept away from the keyframe's measurements
// at that level or the next coarser one and from the points just made.
//
// Finer measurements must not count: a few hundred level-0 points, each
// blocking min_distance level pixels (8 level-0 pixels at level 1, 32 at
// level 3), would cover the coarse levels entirely, leaving the map without
// the coarse points the tracker's coarse stage searches.
#include <vector>

#include <Eigen/Core>

#include "core/image/fast_detector.hpp"
#include "core/map/keyframe.hpp"

namespace facadeslam {

class NewPointCandidates {
 public:
  // `min_distance` in level pixels.
  NewPointCandidates(const KeyFrame& keyframe, int level, double min_distance);

  // The level's corners, strongest first.
  const std::vector<Corner>& corners() const { return corners_; }
  // Closer than min_distance to a measurement or to a point taken here.
  bool near_taken(const Eigen::Vector2d& level_pixel) const;
  // A new point now stands at `level_pixel`.
  void take(const Eigen::Vector2d& level_pixel) { taken_.push_back(level_pixel); }

 private:
  std::vector<Corner> corners_;
  std::vector<Eigen::Vector2d> taken_;  // level pixels
  double min_distance2_;
};

}  // namespace facadeslam
