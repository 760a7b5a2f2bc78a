#pragma once
// What a replay records frame by frame: counts and the tracker's stage
// timings (the trajectories are the System's: System::final_trajectory).
#include <cstddef>
#include <vector>

#include "core/util/json.hpp"
#include "slam/system.hpp"

namespace facadeslam::apps {

// Resources at one moment of a run: the soak's memory and time curves.
struct ResourceSample {
  std::size_t frames = 0;     // frames processed so far
  double resident_mib = 0.0;  // the process's resident memory (0 where unknown)
  std::size_t keyframes = 0, points = 0;
  double frame_ms_median = 0.0;    // over the frames since the previous sample
  double tracker_ms_median = 0.0;  // ... of those tracked (0 if none)
};

struct ReplayLog {
  // A resource sample every this many frames.
  static constexpr std::size_t kSampleEvery = 100;

  // tracked: frames with a pose (the initialised ones too) except the
  // relocalised ones, which `relocalisations` counts.
  std::size_t frames = 0, tracked = 0, lost = 0, relocalisations = 0;
  // Frames given to the tracker (after the map was initialised), and those
  // of them it tracked.
  std::size_t after_initialisation = 0, tracked_after_initialisation = 0;
  // Of unreliable classes, summed over the frames: not searched / down-weighted.
  std::size_t points_dropped = 0, points_down_weighted = 0, points_verified = 0;
  std::vector<double> pyramid_ms, coarse_ms, fine_ms, pose_ms, snapshot_ms, tracker_ms, total_ms;

  // `initialised`: whether the system had a map at this frame (a frame
  // without a pose counts as lost only then).
  void add(const FrameReport& report, bool initialised);
  // After add(): takes a resource sample every kSampleEvery frames.
  void sample_resources(const System& system);
  std::vector<ResourceSample> resources;
  // {"every_frames": kSampleEvery, "frames": [...], "resident_mib": [...],
  //  "keyframes": [...], "points": [...], "frame_ms_median": [...],
  //  "tracker_ms_median": [...]}: columns, short enough for long runs.
  Json resources_json() const;
  // {"pyramid_fast": {median_ms, p95_ms, mean_ms}, "coarse": ..., "fine": ...,
  //  "pose_update": ..., "frame_total": ...}
  Json timings() const;

 private:
  std::size_t tracker_ms_at_last_sample_ = 0;
};

// median_ms, p95_ms and mean_ms of `ms` (an empty object when empty).
Json timing_summary(std::vector<double> ms);

}  // namespace facadeslam::apps
