#pragma once
// What a replay records frame by frame: counts and the tracker's stage
// timings (the trajectories are the System's: System::final_trajectory).
#include <cstddef>
#include <vector>

#include "core/util/json.hpp"
#include "slam/system.hpp"

namespace facadeslam::apps {

struct ReplayLog {
  std::size_t frames = 0, tracked = 0, lost = 0, relocalisations = 0;
  // Of unreliable classes, summed over the frames: not searched / down-weighted.
  std::size_t points_dropped = 0, points_down_weighted = 0;
  std::vector<double> pyramid_ms, coarse_ms, fine_ms, pose_ms, snapshot_ms, tracker_ms, total_ms;

  // `initialised`: whether the system had a map at this frame (a frame
  // without a pose counts as lost only then).
  void add(const FrameReport& report, bool initialised);
  // {"pyramid_fast": {median_ms, p95_ms, mean_ms}, "coarse": ..., "fine": ...,
  //  "pose_update": ..., "frame_total": ...}
  Json timings() const;
};

// median_ms, p95_ms and mean_ms of `ms` (an empty object when empty).
Json timing_summary(std::vector<double> ms);

}  // namespace facadeslam::apps
