#pragma once
// What the tracker hands the map maker when it decides a frame should become
// a keyframe: the frame's images and pose and the map points it found in it.
// The map maker turns it into a KeyFrame (tracker and map maker share only
// the Map and this queue).
#include <memory>
#include <vector>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/image/image_pyramid.hpp"
#include "core/lie/se3.hpp"
#include "core/map/map_point.hpp"

namespace facadeslam {

struct TrackedMeasurement {
  std::shared_ptr<MapPoint> point;
  int level = 0;                // pyramid level it was found at
  Eigen::Vector2d pixel{0, 0};  // level-0 pixels
};

struct KeyFrameCandidate {
  std::size_t frame_index = 0;
  double timestamp = 0.0;
  SE3d T_c_w;
  std::shared_ptr<const ImagePyramid> pyramid;
  cv::Mat colour;          // 8-bit BGR
  cv::Mat small_blurred;   // for relocalisation
  std::vector<TrackedMeasurement> measurements;
  // Requested because the camera turned near an existing keyframe rather than
  // moved away from every keyframe: the map maker gives it depth-prior
  // points for the part of the view no keyframe has a baseline to.
  bool turned_on_the_spot = false;
};

}  // namespace facadeslam
