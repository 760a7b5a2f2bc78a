#pragma once
// Which map points label-aware SLAM trusts less: those whose own label (the
// votes of the point's own views, MapPoint::own_label) is one of the
// unreliable classes (cars drive off, trees sway, the sky has no depth) with
// at least the minimum confidence. The tracker and the map maker's bundle
// adjustment ask the same question.
#include "core/map/map_point.hpp"
#include "core/map/semantic_classes.hpp"

namespace facadeslam {

struct UnreliableLabels {
  ClassSet classes;  // none: labels are ignored
  float min_confidence = 0.5f;
  // Also a point in a moving region (MapPoint::in_moving_region), whatever
  // its label: set for the moving classes, whose regions the semantic worker
  // detects.
  bool regions = false;

  bool any() const { return classes.any(); }
  bool operator==(const UnreliableLabels&) const = default;
  bool contains(const MapPoint& point) const;
};

}  // namespace facadeslam
