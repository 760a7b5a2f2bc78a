#pragma once
// Which map points the map maker removes after each bundle adjustment. Three
// rules, each for a point that no longer earns its place:
// - PTAM's outlier rule: the tracker searched for it at least `min_searches`
//   times and found it less than `max_found_ratio` of them;
// - too few views: fewer than two keyframes measure it, once its source
//   keyframe is no longer among the last `grace_keyframes` made (keyframe
//   ids: culled keyframes count) (a depth-prior point waits there for its
//   second view);
// - left out for its class (a moving class, or a moving region: the tracker
//   does not search it, bundle adjustment does not use it) and measured by
//   none of the last `grace_keyframes` made: nothing uses it any more, and
//   neither rule above can see it. Under traffic such points were half the map (street-traffic with
//   true labels: 997 of 1902 points). A parked car's points that the tracker
//   does measure (it searches them where few other points are in view) keep
//   being measured by new keyframes and stay.
#include <functional>
#include <memory>
#include <vector>

#include "core/map/keyframe.hpp"
#include "core/map/map_point.hpp"

namespace facadeslam {

struct PointCullingOptions {
  int min_searches = 20;
  double max_found_ratio = 0.2;
  KeyFrame::Id grace_keyframes = 3;
};

// Whether a point is left out for its class (UnreliableLabels::contains of
// the moving classes); empty: no point is.
using IsLeftOut = std::function<bool(const MapPoint&)>;

// The points of `points` to remove, in their order. `keyframes`: all the
// map's keyframes (their measurements say which keyframes see which point).
std::vector<std::shared_ptr<MapPoint>> points_to_cull(const std::vector<std::shared_ptr<KeyFrame>>& keyframes,
                                                      const std::vector<std::shared_ptr<MapPoint>>& points,
                                                      const PointCullingOptions& options,
                                                      const IsLeftOut& left_out = {});

}  // namespace facadeslam
