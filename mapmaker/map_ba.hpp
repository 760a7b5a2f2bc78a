#pragma once
// Bundle adjustment of the shared Map: copies the keyframes and points taking
// part into a BaProblem (Map::read), solves without any lock (the tracker
// keeps running), then writes poses and positions back in one short
// exclusive section (Map::update). Outlier measurements (except a point's
// source measurement) are dropped from their keyframes. An aborted solve
// publishes its last accepted iterate too (report.ba.aborted says so).
//
// Map maker thread only (the only writer of poses, points and measurements).
#include <functional>
#include <optional>

#include "core/camera/camera.hpp"
#include "core/map/map.hpp"
#include "mapmaker/ba/ba_selection.hpp"
#include "mapmaker/ba/bundle_adjuster.hpp"
#include "mapmaker/ground_gauge.hpp"

namespace facadeslam {

struct MapBaReport {
  BaResult ba;
  std::size_t keyframes = 0, points = 0, observations = 0;
  std::size_t outliers_removed = 0;
  std::size_t ground_keyframes = 0;  // keyframes held by the ground gauge
};

// Local BA around `newest` (with `selection` neighbours) when given,
// otherwise a global BA (first keyframe fixed, scale anchored on the second).
// `weight_of` gives each point's measurements their weight in the cost, in
// [0, 1] (none: 1 for all); it is asked once per point per call. A point of
// weight 0 (a moving class) is left out altogether: out of the selection, the
// solve and the outlier test. A weight outside [0, 1] throws, naming the point.
// `ground`, when given, adds its ground observations (the free keyframes'
// in a local BA, every keyframe's in a global one).
using PointWeight = std::function<double(const MapPoint&)>;
MapBaReport adjust_map(Map& map, const Camera& camera, const BundleAdjuster& adjuster,
                       std::optional<KeyFrame::Id> newest, const LocalBaOptions& selection = {},
                       const PointWeight& weight_of = {}, GroundGauge* ground = nullptr);

}  // namespace facadeslam
