#pragma once
// A map point seen in an image. The one type for it through the threads:
// the tracker's inliers travel to the map maker as PointMeasurements, the
// map maker keeps them in its keyframes as Measurements (keyed by point), and
// hands its new ones to the semantic worker as PointMeasurements again. The
// solvers take their own flat copies (PoseMeasurement, BaObservation: world
// positions and weights, indices into their problem), so that they do not
// depend on the map.
#include <map>
#include <memory>

#include <Eigen/Core>

#include "core/map/map_point.hpp"

namespace facadeslam {

// Where a map point was seen in a keyframe.
struct Measurement {
  int level = 0;                // pyramid level it was found at
  Eigen::Vector2d pixel{0, 0};  // level-0 pixel coordinates
  bool from_source = false;     // this keyframe is the point's source
};

using Measurements = std::map<MapPoint::Id, Measurement>;

// A point and where it was seen.
struct PointMeasurement {
  std::shared_ptr<MapPoint> point;
  int level = 0;                // pyramid level it was found at
  Eigen::Vector2d pixel{0, 0};  // level-0 pixels
};

}  // namespace facadeslam
