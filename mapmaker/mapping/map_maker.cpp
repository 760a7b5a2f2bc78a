#include "mapmaker/mapping/map_maker.hpp"

#include <chrono>
#include <cmath>
#include <map>
#include <mutex>
#include <shared_mutex>

#include <spdlog/spdlog.h>

#include "mapmaker/mapping/epipolar_partner.hpp"
#include "mapmaker/mapping/epipolar_search.hpp"
#include "mapmaker/mapping/map_ba.hpp"
#include "mapmaker/mapping/point_geometry.hpp"

namespace facadeslam {
namespace {

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) { return std::chrono::duration<double, std::milli>(Clock::now() - t0).count(); }

// A map needs at least this many points to track from.
constexpr std::size_t kMinInitialPoints = 30;

// Keyframes a single-view (depth-prior) point may wait for a second view.
constexpr KeyFrame::Id kSingleViewGraceKeyframes = 3;

}  // namespace

MapMaker::MapMaker(Camera camera, Map& map, KeyFrameQueue& queue, MapMakerOptions options)
    : camera_(std::move(camera)), map_(map), queue_(queue), options_(std::move(options)) {}

MapMaker::~MapMaker() { stop(); }

MapMakerStats MapMaker::stats() const {
  std::lock_guard lock(stats_mutex_);
  return stats_;
}

std::optional<SE3d> MapMaker::initialise(const TwoViewResult& result, const MapMakerFrame& first,
                                         const MapMakerFrame& second) {
  auto kf0 = std::make_shared<KeyFrame>(map_.new_keyframe_id(), first.timestamp, SE3d(), first.pyramid,
                                        first.colour, first.small_blurred);
  auto kf1 = std::make_shared<KeyFrame>(map_.new_keyframe_id(), second.timestamp, result.T_c1_c0, second.pyramid,
                                        second.colour, second.small_blurred);
  std::vector<std::shared_ptr<MapPoint>> points;
  for (std::size_t i = 0; i < result.points_c0.size(); ++i) {
    const PatchSource source{kf0->id(), first.pyramid, 0, result.pixels0[i]};
    auto p = std::make_shared<MapPoint>(map_.new_point_id(), source,
                                        source_geometry(camera_, SE3d(), source, result.points_c0[i]));
    kf0->measurements()[p->id()] = {0, result.pixels0[i], true};
    kf1->measurements()[p->id()] = {0, result.pixels1[i], false};
    points.push_back(std::move(p));
  }
  map_.add({kf0, kf1}, points);
  update_depth_stats(*kf0);
  update_depth_stats(*kf1);
  // The initialiser's points are level-0 corners only: with enough parallax,
  // search both keyframes' corners at every level against the other one for
  // the coarse-level points the tracker's coarse stage needs to survive fast
  // motion (map_maker_options.hpp).
  if (result.median_parallax_deg >= options_.densify_initial_map_min_parallax_deg)
    for (const auto& [newest, other] : {std::pair{kf1, kf0}, std::pair{kf0, kf1}}) {
      auto more = epipolar_new_points(map_, camera_, *newest, *other, options_.epipolar);
      map_.add({}, more);
      points.insert(points.end(), more.begin(), more.end());
    }

  const auto t0 = Clock::now();
  const MapBaReport ba = adjust_map(map_, camera_, BundleAdjuster(options_.global_ba), std::nullopt);
  remove_outlier_points();
  update_depth_stats(*kf0);
  update_depth_stats(*kf1);
  spdlog::info("map initialised from frames {} and {}: {} points ({} model), BA {:.2f} -> {:.2f} px in {:.0f} ms",
               first.index, second.index, map_.point_count(), to_string(result.model), ba.ba.initial_rms_px,
               ba.ba.final_rms_px, ms_since(t0));
  if (map_.point_count() < kMinInitialPoints) {
    spdlog::warn("initial map has only {} points; discarding it", map_.point_count());
    map_.clear();
    return std::nullopt;
  }
  {
    std::lock_guard lock(stats_mutex_);
    stats_.keyframes_added += 2;
    stats_.points_created += points.size();
    stats_.global_ba_runs += 1;
    stats_.global_ba_ms += ba.ba.time_ms;
  }
  std::vector<std::shared_ptr<MapPoint>> alive;
  for (const auto& p : points)
    if (!p->is_bad() && map_.point(p->id())) alive.push_back(p);
  publish_new_points(kf0, std::move(alive));
  std::shared_lock lock(map_.mutex());
  return kf1->T_c_w();
}

void MapMaker::update_depth_stats(KeyFrame& keyframe) {
  std::vector<double> depths;
  std::shared_lock lock(map_.mutex());
  for (const auto& [id, m] : keyframe.measurements()) {
    const auto p = map_.point_locked(id);
    if (!p) continue;
    const double z = (keyframe.T_c_w() * p->position()).z();
    if (z > 0) depths.push_back(z);
  }
  lock.unlock();
  if (depths.empty()) return;
  // Median and a robust spread: facades give heavy-tailed depth distributions.
  std::sort(depths.begin(), depths.end());
  const double median = depths[depths.size() / 2];
  std::vector<double> deviations;
  for (double d : depths) deviations.push_back(std::abs(d - median));
  std::sort(deviations.begin(), deviations.end());
  const double sigma = 1.4826 * deviations[deviations.size() / 2];
  std::unique_lock write(map_.mutex());
  keyframe.set_depth_stats(median, sigma);
}

std::shared_ptr<KeyFrame> MapMaker::epipolar_partner(const KeyFrame& keyframe) const {
  std::vector<std::shared_ptr<KeyFrame>> others;
  std::vector<SE3d> poses;
  SE3d T_new_w;
  double depth = 1.0;
  {
    const auto keyframes = map_.keyframes();
    std::shared_lock lock(map_.mutex());
    for (const auto& kf : keyframes)
      if (kf->id() != keyframe.id()) {
        others.push_back(kf);
        poses.push_back(kf->T_c_w());
      }
    T_new_w = keyframe.T_c_w();
    depth = keyframe.mean_depth();
  }
  const auto choice = choose_epipolar_partner(T_new_w, depth, poses, options_.epipolar_partner);
  return choice ? others[*choice] : nullptr;
}

void MapMaker::add_keyframe(KeyFrameCandidate candidate) {
  const auto t0 = Clock::now();
  auto kf = std::make_shared<KeyFrame>(map_.new_keyframe_id(), candidate.timestamp, candidate.T_c_w,
                                       candidate.pyramid, candidate.colour, candidate.small_blurred);
  for (const auto& m : candidate.measurements)
    if (!m.point->is_bad() && map_.point(m.point->id())) kf->measurements()[m.point->id()] = {m.level, m.pixel, false};
  map_.add_keyframe(kf);
  update_depth_stats(*kf);

  std::vector<std::shared_ptr<MapPoint>> created;
  if (const auto other = epipolar_partner(*kf)) {
    EpipolarSearchStats es;
    created = epipolar_new_points(map_, camera_, *kf, *other, options_.epipolar, &es);
    map_.add({}, created);
    const auto& by_level = es.triangulated_per_level;
    spdlog::debug(
        "keyframe {} (frame {}): {} tracked, epipolar search with keyframe {}: {} tried, {} matched, {} new "
        "(levels 0-3: {} {} {} {})",
        kf->id(), candidate.frame_index, candidate.measurements.size(), other->id(), es.candidates, es.matched,
        es.triangulated, by_level[0], by_level[1], by_level[2], by_level[3]);
  }
  if (options_.depth_prior_points && candidate.turned_on_the_spot) {
    auto more = depth_prior_points(map_, camera_, *kf, options_.depth_prior);
    spdlog::debug("keyframe {} (frame {}): turning on the spot, {} points at a prior depth", kf->id(),
                  candidate.frame_index, more.size());
    map_.add({}, more);
    created.insert(created.end(), more.begin(), more.end());
  }

  const MapBaReport ba =
      adjust_map(map_, camera_, BundleAdjuster(options_.local_ba), kf->id(), options_.local_ba_selection);
  remove_outlier_points();
  update_depth_stats(*kf);
  {
    std::lock_guard lock(stats_mutex_);
    stats_.keyframes_added += 1;
    stats_.points_created += created.size();
    stats_.local_ba_runs += 1;
    stats_.local_ba_ms += ba.ba.time_ms;
    stats_.keyframe_ms += ms_since(t0);
  }
  map_changed_since_global_ba_ = true;
  ++keyframes_since_global_ba_;
  std::erase_if(created, [&](const auto& p) { return p->is_bad() || !map_.point(p->id()); });
  publish_new_points(kf, std::move(created));
}

void MapMaker::remove_outlier_points() {
  // Measurement counts over all keyframes (map maker thread owns them).
  const auto keyframes = map_.keyframes();
  std::map<MapPoint::Id, int> measured;
  KeyFrame::Id newest = 0;
  for (const auto& kf : keyframes) {
    newest = std::max(newest, kf->id());
    for (const auto& [id, m] : kf->measurements()) ++measured[id];
  }
  for (const auto& p : map_.points()) {
    const bool rarely_found =
        p->times_searched() >= static_cast<std::uint32_t>(options_.outlier_min_searches) &&
        p->times_found() < options_.outlier_max_found_ratio * p->times_searched();
    const auto it = measured.find(p->id());
    // A point seen by one keyframe only is kept while its keyframe is among
    // the newest few: a depth-prior point waits there for its second view.
    const bool awaiting_second_view = p->source().keyframe_id + kSingleViewGraceKeyframes > newest;
    const bool too_few_views = it == measured.end() || (it->second < 2 && !awaiting_second_view);
    if (rarely_found || too_few_views) p->mark_bad();
  }
  const auto removed = map_.remove_bad_points();
  if (removed.empty()) return;
  for (const auto& kf : keyframes)
    for (const auto id : removed) kf->measurements().erase(id);
  std::lock_guard lock(stats_mutex_);
  stats_.points_removed += removed.size();
}

void MapMaker::publish_new_points(const std::shared_ptr<KeyFrame>& keyframe,
                                  std::vector<std::shared_ptr<MapPoint>> points) {
  if (on_new_points_ && !points.empty()) on_new_points_(keyframe, points);
}

void MapMaker::run_global_ba() {
  abort_global_ba_ = false;
  BundleAdjusterOptions options = options_.global_ba;
  options.abort = &abort_global_ba_;
  // Abandon the global BA as soon as the tracker queues a keyframe: local
  // mapping around new keyframes matters more than polishing the old map.
  options.on_iteration = [this](int) {
    if (!queue_.empty()) abort_global_ba_ = true;
  };
  const MapBaReport ba = adjust_map(map_, camera_, BundleAdjuster(options), std::nullopt);
  std::lock_guard lock(stats_mutex_);
  if (ba.ba.aborted) {
    ++stats_.global_ba_aborted;
    return;
  }
  ++stats_.global_ba_runs;
  stats_.global_ba_ms += ba.ba.time_ms;
  map_changed_since_global_ba_ = false;
  keyframes_since_global_ba_ = 0;
}

void MapMaker::process_pending() {
  while (auto candidate = queue_.try_pop()) {
    add_keyframe(std::move(*candidate));
    if (keyframes_since_global_ba_ >= static_cast<std::size_t>(options_.sync_global_ba_every)) {
      run_global_ba();
      remove_outlier_points();
    }
  }
}

void MapMaker::start() {
  if (thread_.joinable()) return;
  thread_ = std::thread([this] { run(); });
}

void MapMaker::stop() {
  if (!thread_.joinable()) return;
  queue_.close();
  thread_.join();
}

void MapMaker::run() {
  for (;;) {
    queue_.wait_until([&] { return map_changed_since_global_ba_; });
    if (auto candidate = queue_.try_pop()) {
      add_keyframe(std::move(*candidate));
      continue;
    }
    if (queue_.closed()) break;
    if (map_changed_since_global_ba_) {
      run_global_ba();
      remove_outlier_points();
    }
  }
}

}  // namespace facadeslam
