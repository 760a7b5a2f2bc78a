#pragma once
// Which keyframes and points take part in a bundle adjustment, decided on a
// plain description of the map (ids, camera centres, who observes what) so
// that it is testable without a Map.
//
// Local BA (PTAM's "recent" bundle adjustment):
//   free keyframes  = the newest keyframe + its N nearest keyframes by
//                     camera-centre distance (N = 4 by default; ties broken
//                     by smaller id). The gauge keyframe (the map's first,
//                     i.e. smallest id) is never made free: it is skipped
//                     when picking neighbours, so a small map still has a
//                     fixed keyframe.
//   free points     = every point observed by a free keyframe;
//   fixed keyframes = every other keyframe that observes a free point (they
//                     constrain the free points and, with two or more of them,
//                     the scale).
// Global BA: every keyframe free except the gauge keyframe (fixed); every
// observed point free. Points observed by no keyframe take no part.
#include <cstddef>
#include <cstdint>
#include <set>
#include <vector>

#include <Eigen/Core>

namespace facadeslam {

struct KeyFrameCentre {
  std::uint64_t id = 0;
  Eigen::Vector3d centre_w{0, 0, 0};  // camera centre in the world frame
};

struct ObservationRef {
  std::uint64_t keyframe_id = 0;
  std::uint64_t point_id = 0;
};

struct BaSelection {
  std::set<std::uint64_t> free_keyframes;
  std::set<std::uint64_t> fixed_keyframes;
  std::set<std::uint64_t> free_points;
};

struct LocalBaOptions {
  std::size_t neighbours = 4;  // nearest keyframes freed with the newest one
};

// Throws Error when the ids repeat, a centre is not finite, `newest` is not
// among the keyframes, or an observation names an unknown keyframe.
BaSelection local_ba_selection(const std::vector<KeyFrameCentre>& keyframes,
                               const std::vector<ObservationRef>& observations, std::uint64_t newest,
                               const LocalBaOptions& options = {});

// Throws Error when the ids repeat, the list is empty or an observation names
// an unknown keyframe. (Centres are not used.)
BaSelection global_ba_selection(const std::vector<KeyFrameCentre>& keyframes,
                                const std::vector<ObservationRef>& observations);

}  // namespace facadeslam
