#pragma once
// What the tracker hands the map maker when it decides a frame should become
// a keyframe: the frame itself, its pose and the map points it found in it.
// The map maker turns it into a KeyFrame (tracker and map maker share only
// the Map and this queue).
#include <memory>
#include <vector>

#include <Eigen/Core>

#include "core/image/frame.hpp"
#include "core/lie/se3.hpp"
#include "core/map/measurement.hpp"
#include "core/util/blocking_queue.hpp"

namespace facadeslam {

struct KeyFrameCandidate {
  Frame frame;
  SE3d T_c_w;
  std::vector<PointMeasurement> measurements;  // the tracker's inliers in the frame
  // Requested because the camera turned near an existing keyframe rather than
  // moved away from every keyframe: the map maker gives it depth-prior
  // points for the part of the view no keyframe has a baseline to.
  bool turned_on_the_spot = false;
};

// The tracker -> map maker hand-off.
using KeyFrameQueue = BlockingQueue<KeyFrameCandidate>;

}  // namespace facadeslam
