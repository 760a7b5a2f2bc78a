#include "core/map/unreliable_labels.hpp"

namespace facadeslam {

bool UnreliableLabels::contains(const MapPoint& point) const {
  if (classes.none()) return false;
  if (regions && point.in_moving_region()) return true;
  const SemanticLabel label = point.own_label();
  return label.label < classes.size() && classes.test(label.label) && label.confidence >= min_confidence;
}

}  // namespace facadeslam
