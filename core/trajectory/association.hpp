#pragma once
// Pairs the poses of an estimate with those of the ground truth by time, as
// TUM's associate.py does: among all (gt, est) pairs whose timestamps differ
// by at most `max_dt`, the closest pairs are taken first and each pose of
// either trajectory is used at most once.
#include <cstddef>
#include <vector>

#include "core/trajectory/trajectory.hpp"

namespace facadeslam {

struct AssociatedPair {
  std::size_t gt_index = 0;
  std::size_t est_index = 0;
};

// Default tolerance: the TUM benchmark's 10 ms.
inline constexpr double kDefaultMaxTimeDifference = 0.01;

// Pairs sorted by estimate time. |dt| <= max_dt counts as a match, with 1 µs of
// slack: timestamps such as 1305031098.6659 are stored as doubles whose
// spacing near 1.3e9 s is 0.24 µs, so a pair exactly `max_dt` apart in the
// file must not depend on rounding. Throws Error if max_dt is negative or not
// finite. Expects timestamps in time order (as read_trajectory guarantees).
std::vector<AssociatedPair> associate_by_time(const Trajectory& gt, const Trajectory& est,
                                              double max_dt = kDefaultMaxTimeDifference);

}  // namespace facadeslam
