#pragma once
// How label-aware SLAM treats a map point by its own label (the votes of its
// own views, MapPoint::own_label): one policy, read by the tracker (search,
// pose weights, verification), bundle adjustment (per-point weights) and the
// map maker's point culling alike. The rules and the figures behind them:
// docs/design.md, "Decision records".
// - Unreliable classes (vegetation, sky, various: swaying, no depth, mixed)
//   are weighed down in the tracker's pose update; geometry has the last
//   word: one the pose puts within `verify_px` of its measurement gets its
//   full weight after all.
// - Moving classes (cars), or points in a region dense with calls of one,
//   are left out: by the tracker (unless fewer than `min_reliable_points`
//   others are in view), by bundle adjustment, and culled once no new
//   keyframe measures them. A car's points move as one body and agree with
//   one another on a wrong motion that no robust weight rejects.
// With no classes (semantics off) labels are ignored.
#include "core/map/map_point.hpp"
#include "core/map/unreliable_labels.hpp"

namespace facadeslam {

struct LabelPolicy {
  UnreliableLabels unreliable;     // weighed down in the pose update
  UnreliableLabels moving;         // left out altogether
  double unreliable_weight = 0.1;  // x Tukey's weight (0: not searched, like a moving point)
  int min_reliable_points = 100;   // fewer other points in view: left-out points are searched after all
  double verify_px = 2.0;          // search-level pixels; 0: never verified

  // Whether any point can be left out (else bundle adjustment and culling
  // need not ask point by point).
  bool leaves_points_out() const { return moving.any(); }
  // Left out of tracking, bundle adjustment and the map (once unmeasured).
  bool left_out(const MapPoint& point) const { return moving.contains(point); }
  // The point's weight in the tracker's pose update (0: not searched).
  double tracking_weight(const MapPoint& point) const {
    if (left_out(point)) return 0.0;
    return unreliable.contains(point) ? unreliable_weight : 1.0;
  }
  // ... and in bundle adjustment: the tracker's down-weighting is about one
  // frame's pose; a still tree measured from several keyframes is good
  // structure, so only left-out points leave.
  double ba_weight(const MapPoint& point) const { return left_out(point) ? 0.0 : 1.0; }
};

}  // namespace facadeslam
