#pragma once
// The map maker -> semantic worker hand-off: a keyframe and the points it
// just gave the map (their patches are in that keyframe's images), to be
// labelled there.
#include <memory>
#include <vector>

#include "core/map/keyframe.hpp"
#include "core/map/map_point.hpp"
#include "core/util/blocking_queue.hpp"

namespace facadeslam {

struct KeyFramePoints {
  std::shared_ptr<const KeyFrame> keyframe;
  std::vector<std::shared_ptr<MapPoint>> points;  // sources in `keyframe`
};

using KeyFramePointsQueue = BlockingQueue<KeyFramePoints>;

}  // namespace facadeslam
