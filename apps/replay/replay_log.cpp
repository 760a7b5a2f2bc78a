#include "apps/replay/replay_log.hpp"

#include <algorithm>

namespace facadeslam::apps {

Json timing_summary(std::vector<double> ms) {
  Json j = Json::object();
  if (ms.empty()) return j;
  std::sort(ms.begin(), ms.end());
  double sum = 0;
  for (double v : ms) sum += v;
  j["median_ms"] = ms[ms.size() / 2];
  j["p95_ms"] = ms[std::min(ms.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(ms.size())))];
  j["mean_ms"] = sum / static_cast<double>(ms.size());
  return j;
}

void ReplayLog::add(const FrameReport& r, bool initialised) {
  ++frames;
  if (r.has_pose) {
    ++tracked;
  } else if (initialised) {
    ++lost;
  }
  relocalisations += r.status == FrameStatus::relocalised;
  points_dropped += static_cast<std::size_t>(r.tracking.points_dropped);
  points_down_weighted += static_cast<std::size_t>(r.tracking.points_down_weighted);
  pyramid_ms.push_back(r.pyramid_ms);
  total_ms.push_back(r.total_ms);
  if (r.status == FrameStatus::tracking || r.status == FrameStatus::relocalised) {
    coarse_ms.push_back(r.tracking.timings.coarse_ms);
    fine_ms.push_back(r.tracking.timings.fine_ms);
    pose_ms.push_back(r.tracking.timings.pose_ms);
    snapshot_ms.push_back(r.tracking.timings.snapshot_ms);
    const StageTimings& t = r.tracking.timings;
    tracker_ms.push_back(r.pyramid_ms + t.snapshot_ms + t.coarse_ms + t.fine_ms + t.pose_ms + t.relocalise_ms);
  }
}

Json ReplayLog::timings() const {
  Json t = Json::object();
  t["pyramid_fast"] = timing_summary(pyramid_ms);
  t["coarse"] = timing_summary(coarse_ms);
  t["fine"] = timing_summary(fine_ms);
  t["map_snapshot"] = timing_summary(snapshot_ms);
  // The tracker's own work per tracked frame (pyramid + FAST, map
  // snapshot, both search stages, pose updates, relocalisation); frame_total
  // adds start-up frames and, threaded, waits on the map's lock.
  t["tracker"] = timing_summary(tracker_ms);
  t["pose_update"] = timing_summary(pose_ms);
  t["frame_total"] = timing_summary(total_ms);
  return t;
}

}  // namespace facadeslam::apps
