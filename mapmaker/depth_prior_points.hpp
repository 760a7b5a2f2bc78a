#pragma once
// New points for a keyframe taken while the camera turns on the spot.
//
// Epipolar search needs a second view with a baseline; when the camera only
// rotates, no keyframe gives one for the part of the scene that is coming
// into view, and PTAM runs out of map and is lost (Pirchheim et al., ISMAR
// 2013, "Handling pure camera rotation in keyframe-based SLAM"). Under a
// pure rotation a point projects to the same pixel whatever its depth, so
// such a view can still be tracked from points whose depth is only a prior:
// each strong FAST corner away from the keyframe's measurements becomes a
// point at the depth of the measured points nearest to it in the image
// (facades continue past the mapped part at similar depth). Bundle
// adjustment then fixes the depth once a keyframe with a baseline measures
// the point; until then its depth stays near the prior (Levenberg-Marquardt
// damping), which the tracker does not notice while the camera only turns.
//
// Map maker thread only.
#include <array>
#include <memory>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/map/map.hpp"

namespace facadeslam {

struct DepthPriorOptions {
  // Corners per pyramid level (strongest first); level 3 is left to the
  // epipolar search: its few corners cover too much of the scene each.
  std::array<int, 4> max_points_per_level{{150, 75, 30, 0}};
  double min_distance_to_measurement = 8.0;  // level pixels
  int depth_neighbours = 5;                  // measured points whose median depth is the prior
};

// Creates the points (source and one measurement in `keyframe`); returns
// them unpublished, as epipolar_new_points does.
NewPoints depth_prior_points(Map& map, const Camera& camera, const std::shared_ptr<KeyFrame>& keyframe,
                             const DepthPriorOptions& options = {});

}  // namespace facadeslam
