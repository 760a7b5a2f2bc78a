#include "apps/replay/replay_log.hpp"

#include <algorithm>

#include "core/util/median.hpp"
#include "core/util/resident_memory.hpp"

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
  // A relocalised frame came back after a loss: it is counted as such, not
  // as tracked (the loss it ends must not be hidden).
  if (r.status == FrameStatus::relocalised) {
    ++relocalisations;
  } else if (r.has_pose) {
    ++tracked;
  } else if (initialised) {
    ++lost;
  }
  after_initialisation +=
      r.status == FrameStatus::tracking || r.status == FrameStatus::relocalised || r.status == FrameStatus::lost;
  tracked_after_initialisation += r.status == FrameStatus::tracking;
  points_dropped += static_cast<std::size_t>(r.tracking.points_dropped);
  points_down_weighted += static_cast<std::size_t>(r.tracking.points_down_weighted);
  points_verified += static_cast<std::size_t>(r.tracking.points_verified);
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

namespace {

// The entries of `all` after the first `from`.
std::vector<double> tail(const std::vector<double>& all, std::size_t from) {
  return {all.begin() + static_cast<std::ptrdiff_t>(std::min(from, all.size())), all.end()};
}

}  // namespace

void ReplayLog::sample_resources(const System& system) {
  if (frames == 0 || frames % kSampleEvery != 0) return;
  ResourceSample s;
  s.frames = frames;
  s.resident_mib = static_cast<double>(resident_memory_bytes().value_or(0)) / (1024.0 * 1024.0);
  s.keyframes = system.map().keyframe_count();
  s.points = system.map().point_count();
  s.frame_ms_median = median(tail(total_ms, frames - kSampleEvery));
  s.tracker_ms_median = median(tail(tracker_ms, tracker_ms_at_last_sample_));
  tracker_ms_at_last_sample_ = tracker_ms.size();
  resources.push_back(s);
}

Json ReplayLog::resources_json() const {
  Json frames_column = Json::array(), resident = Json::array(), keyframes = Json::array(), points = Json::array(),
       frame_ms = Json::array(), tracker = Json::array();
  for (const ResourceSample& s : resources) {
    frames_column.push_back(s.frames);
    resident.push_back(s.resident_mib);
    keyframes.push_back(s.keyframes);
    points.push_back(s.points);
    frame_ms.push_back(s.frame_ms_median);
    tracker.push_back(s.tracker_ms_median);
  }
  Json j = Json::object();
  j["every_frames"] = kSampleEvery;
  j["frames"] = frames_column;
  j["resident_mib"] = resident;
  j["keyframes"] = keyframes;
  j["points"] = points;
  j["frame_ms_median"] = frame_ms;
  j["tracker_ms_median"] = tracker;
  return j;
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
