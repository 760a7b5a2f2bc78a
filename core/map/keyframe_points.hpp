#pragma once
// The map maker -> semantic worker hand-off: a keyframe and the points newly
// measured in it (the points it created and the points the tracker found in
// it), each where the keyframe saw it, to be classified there. Every
// measurement is handed over once, so each observation of a point adds one
// set of votes to it.
#include <memory>
#include <vector>

#include "core/map/keyframe.hpp"
#include "core/map/measurement.hpp"
#include "core/map/map_point.hpp"
#include "core/util/blocking_queue.hpp"

namespace facadeslam {

struct KeyFramePoints {
  // Shared: the worker's images stay valid even if the map drops the keyframe.
  std::shared_ptr<const KeyFrame> keyframe;
  std::vector<PointMeasurement> points;  // where the keyframe saw each
};

using KeyFramePointsQueue = BlockingQueue<KeyFramePoints>;

}  // namespace facadeslam
