#pragma once
// Which keyframes the map no longer needs (ORB-SLAM's local keyframe
// culling, adapted to PTAM's measurements): a keyframe most of whose points
// other keyframes measure, at the same scale or a finer one, adds nothing
// but cost to every bundle adjustment, relocalisation and keyframe test
// after it. Without culling a camera that keeps revisiting a place (a
// looped replay, a user walking up and down a street) grows the map by a
// keyframe or two per pass for ever.
#include <cstdint>
#include <map>
#include <set>
#include <vector>

namespace facadeslam {

struct KeyFrameCullingOptions {
  bool enabled = true;
  // A keyframe goes when at least this share of its measurements is
  // redundant ...
  double redundant_share = 0.9;
  // ... a measurement being redundant when at least this many other
  // keyframes measure the same point at its level, a finer one, or one
  // level coarser. ORB-SLAM asks for 3; that also took single passes'
  // slow-motion keyframes, which bundle adjustment was using (street-walk's
  // ATE 0.075 -> 0.112 %, the demo's 0.447 -> 0.494 %); with 4 the loops
  // stay bounded and single passes keep their figures (0.091 %, 0.440 %).
  int min_other_keyframes = 4;
};

// One keyframe's measurements: point id -> the pyramid level it was found at.
using MeasuredLevels = std::map<std::uint64_t, int>;

// The keyframes to cull, in the order they were chosen: candidates are
// visited by ascending id, and a keyframe chosen no longer counts for the
// ones after it. Keyframes in `keep` are never chosen but count for others;
// a keyframe with no measurements is never chosen (nothing shows that it is
// redundant).
std::vector<std::uint64_t> redundant_keyframes(const std::map<std::uint64_t, MeasuredLevels>& keyframes,
                                               const std::set<std::uint64_t>& keep,
                                               const KeyFrameCullingOptions& options);

}  // namespace facadeslam
