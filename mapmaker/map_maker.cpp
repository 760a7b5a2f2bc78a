#include "mapmaker/map_maker.hpp"

#include <cmath>
#include <map>
#include <set>

#include <spdlog/spdlog.h>

#include "core/util/stopwatch.hpp"
#include "mapmaker/epipolar_partner.hpp"
#include "mapmaker/epipolar_search.hpp"
#include "mapmaker/keyframe_culling.hpp"
#include "mapmaker/map_ba.hpp"
#include "mapmaker/point_culling.hpp"
#include "mapmaker/point_geometry.hpp"

namespace facadeslam {
namespace {

// A map needs at least this many points to track from.
constexpr std::size_t kMinInitialPoints = 30;

// Keyframes a single-view (depth-prior) point may wait for a second view,
// and a point left out for its class may go unmeasured (point_culling.hpp).
constexpr KeyFrame::Id kSingleViewGraceKeyframes = 3;

}  // namespace

MapMaker::MapMaker(Camera camera, Map& map, KeyFrameQueue& queue, MapMakerOptions options,
                   KeyFramePointsQueue* new_points)
    : camera_(camera),
      map_(map),
      queue_(queue),
      options_(std::move(options)),
      new_points_(new_points),
      ground_(options_.ground_gauge) {}

void MapMaker::hand_off(const std::shared_ptr<KeyFrame>& keyframe, const NewPoints* only) {
  if (!new_points_ || !keyframe) return;
  std::set<MapPoint::Id> wanted;
  if (only)
    for (const auto& p : only->points) wanted.insert(p->id());
  KeyFramePoints job{keyframe, {}};
  // Measurements: the map maker, their only writer, reads them without a lock.
  for (const auto& [id, m] : keyframe->measurements()) {
    if (only && !wanted.contains(id)) continue;
    auto p = map_.point(id);
    if (p && !p->is_bad()) job.points.push_back({std::move(p), m.level, m.pixel});
  }
  if (!job.points.empty()) new_points_->push(std::move(job));
}

MapMaker::~MapMaker() { stop(); }

MapMakerStats MapMaker::stats() const {
  std::lock_guard lock(stats_mutex_);
  return stats_;
}

std::optional<SE3d> MapMaker::initialise(const InitialViews& views) {
  Measurements first_measurements, second_measurements;
  std::vector<std::shared_ptr<MapPoint>> initial;
  const KeyFrame::Id first_id = map_.new_keyframe_id();
  for (std::size_t i = 0; i < views.points_first.size(); ++i) {
    const PatchSource source{first_id, views.first.pyramid, 0, views.pixels_first[i]};
    auto p = std::make_shared<MapPoint>(map_.new_point_id(), source,
                                        source_geometry(camera_, SE3d(), source, views.points_first[i]));
    first_measurements[p->id()] = {0, views.pixels_first[i], true};
    second_measurements[p->id()] = {0, views.pixels_second[i], false};
    initial.push_back(std::move(p));
  }
  auto kf0 = std::make_shared<KeyFrame>(first_id, views.first, SE3d(), std::move(first_measurements));
  auto kf1 = std::make_shared<KeyFrame>(map_.new_keyframe_id(), views.second, views.T_second_first,
                                        std::move(second_measurements));
  map_.add({kf0, kf1}, initial);
  NewPoints points{std::move(initial), {}};
  update_depth_stats(*kf0);
  update_depth_stats(*kf1);
  // The initialiser's points are level-0 corners only: with enough parallax,
  // search both keyframes' corners at every level against the other one for
  // the coarse-level points the tracker's coarse stage needs to survive fast
  // motion (map_maker_options.hpp).
  if (views.median_parallax_deg >= options_.densify_initial_map_min_parallax_deg)
    for (const auto& [newest, other] : {std::pair{kf1, kf0}, std::pair{kf0, kf1}}) {
      NewPoints more = epipolar_new_points(map_, camera_, newest, other, options_.epipolar);
      map_.add(more);
      points.append(std::move(more));
    }

  const Stopwatch t0;
  const MapBaReport ba =
      adjust_map(map_, camera_, BundleAdjuster(options_.global_ba), std::nullopt, {}, ba_point_weight(), &ground_);
  remove_outlier_points();
  update_depth_stats(*kf0);
  update_depth_stats(*kf1);
  spdlog::info("map initialised from frames {} and {}: {} points ({} model), BA {:.2f} -> {:.2f} px in {:.0f} ms",
               views.first.index, views.second.index, map_.point_count(), views.model, ba.ba.initial_rms_px,
               ba.ba.final_rms_px, t0.elapsed_ms());
  if (map_.point_count() < kMinInitialPoints) {
    spdlog::warn("initial map has only {} points; discarding it", map_.point_count());
    map_.clear();
    return std::nullopt;
  }
  {
    std::lock_guard lock(stats_mutex_);
    stats_.keyframes_added += 2;
    stats_.points_created += points.points.size();
    stats_.global_ba_runs += 1;
    stats_.global_ba_ms += ba.ba.time_ms;
  }
  hand_off(kf0);
  hand_off(kf1);
  return kf1->T_c_w();
}

void MapMaker::update_depth_stats(KeyFrame& keyframe) {
  std::vector<double> depths;
  map_.read([&](const MapView& view) {
    for (const auto& [id, m] : keyframe.measurements()) {
      const auto p = view.point(id);
      if (!p) continue;
      const double z = (keyframe.T_c_w() * p->position()).z();
      if (z > 0) depths.push_back(z);
    }
  });
  if (depths.empty()) return;
  // Median and a robust spread: facades give heavy-tailed depth distributions.
  std::sort(depths.begin(), depths.end());
  const double median = depths[depths.size() / 2];
  std::vector<double> deviations;
  deviations.reserve(depths.size());
  for (double d : depths) deviations.push_back(std::abs(d - median));
  std::sort(deviations.begin(), deviations.end());
  const double sigma = 1.4826 * deviations[deviations.size() / 2];
  map_.update([&](MapEditor& edit) { edit.set_depth_stats(keyframe, median, sigma); });
}

std::vector<std::shared_ptr<KeyFrame>> MapMaker::epipolar_partners(const KeyFrame& keyframe) const {
  // Poses and depths: the map maker, their only writer, reads them without a lock.
  std::vector<std::shared_ptr<KeyFrame>> others;
  std::vector<SE3d> poses;
  for (const auto& kf : map_.keyframes())
    if (kf->id() != keyframe.id()) {
      others.push_back(kf);
      poses.push_back(kf->T_c_w());
    }
  const auto near = choose_epipolar_partner(keyframe.T_c_w(), keyframe.mean_depth(), poses, options_.epipolar_partner);
  if (!near) return {};
  std::vector<std::shared_ptr<KeyFrame>> partners{others[*near]};
  if (!moving_forward(keyframe.T_c_w(), poses[*near], options_.epipolar_partner)) return partners;
  // Forward over the far partner's longer baseline too: a hand-held camera's
  // shake can make one short step look forward on a walk that is not.
  if (const auto far =
          choose_far_epipolar_partner(keyframe.T_c_w(), keyframe.mean_depth(), poses, near, options_.epipolar_partner);
      far && moving_forward(keyframe.T_c_w(), poses[*far], options_.epipolar_partner))
    partners.push_back(others[*far]);
  return partners;
}

void MapMaker::add_keyframe(KeyFrameCandidate candidate) {
  const Stopwatch t0;
  Measurements measurements;
  for (const auto& m : candidate.measurements)
    if (!m.point->is_bad() && map_.point(m.point->id())) measurements[m.point->id()] = {m.level, m.pixel, false};
  auto kf =
      std::make_shared<KeyFrame>(map_.new_keyframe_id(), candidate.frame, candidate.T_c_w, std::move(measurements));
  map_.add_keyframe(kf);
  update_depth_stats(*kf);
  if (options_.newest_view_templates)
    map_.update([&](MapEditor& edit) {
      for (const auto& [id, m] : kf->measurements()) {
        const auto p = edit.point(id);
        if (!p) continue;
        const PatchSource view{kf->id(), kf->pyramid(), m.level, m.pixel};
        edit.set_view(*p, view, source_geometry(camera_, kf->T_c_w(), view, p->position()));
      }
    });

  NewPoints created;
  // Each partner's points are published before the next search, so its
  // candidates keep away from them.
  std::vector<std::pair<std::shared_ptr<KeyFrame>, NewPoints>> by_partner;
  const auto partners = epipolar_partners(*kf);
  // Moving forward (a second, far partner): the search reaches out to the
  // far points ahead; otherwise PTAM's depth range.
  EpipolarSearchOptions search = options_.epipolar;
  if (partners.size() < 2) search.min_far_depth_factor = 0.0;
  for (const auto& other : partners) {
    EpipolarSearchStats es;
    NewPoints found = epipolar_new_points(map_, camera_, kf, other, search, &es);
    map_.add(found);
    created.append(NewPoints{found.points, {}});
    by_partner.emplace_back(other, std::move(found));
    const auto& by_level = es.triangulated_per_level;
    spdlog::debug(
        "keyframe {} (frame {}): {} tracked, epipolar search with keyframe {}: {} tried, {} matched, {} new "
        "(levels 0-3: {} {} {} {})",
        kf->id(), candidate.frame.index, candidate.measurements.size(), other->id(), es.candidates, es.matched,
        es.triangulated, by_level[0], by_level[1], by_level[2], by_level[3]);
  }
  if (options_.depth_prior_points && candidate.turned_on_the_spot) {
    NewPoints more = depth_prior_points(map_, camera_, kf, options_.depth_prior);
    spdlog::debug("keyframe {} (frame {}): turning on the spot, {} points at a prior depth", kf->id(),
                  candidate.frame.index, more.points.size());
    map_.add(more);
    created.append(std::move(more));
  }

  if (!ground_.reference()) {
    ground_.try_reference(map_.keyframe_count(), [this] { return ground_views(); });
    if (const auto& ground = ground_.reference())
      spdlog::info(
          "ground under the first {} keyframes: the camera {:.3f} above it (normal {:.3f} {:.3f} {:.3f}, {} points)",
          map_.keyframe_count(), ground->height, ground->normal_c.x(), ground->normal_c.y(), ground->normal_c.z(),
          ground->inliers);
  }
  const MapBaReport ba = adjust_map(map_, camera_, BundleAdjuster(options_.local_ba), kf->id(),
                                    options_.local_ba_selection, ba_point_weight(), &ground_);
  if (const auto& ground = ground_.reference(); ground && ground_.heights().contains(kf->id()))
    spdlog::debug("keyframe {} (frame {}): ground at {:.3f} x the reference height", kf->id(), candidate.frame.index,
                  ground_.heights().at(kf->id()) / ground->height);
  remove_outlier_points();
  update_depth_stats(*kf);
  {
    std::lock_guard lock(stats_mutex_);
    stats_.keyframes_added += 1;
    stats_.points_created += created.points.size();
    stats_.local_ba_runs += 1;
    stats_.local_ba_ms += ba.ba.time_ms;
    stats_.keyframe_ms += t0.elapsed_ms();
    stats_.ground = ground_.reference();
    stats_.ground_held_local_ba_runs += ba.ground_keyframes > 0 ? 1 : 0;
  }
  map_changed_since_global_ba_ = true;
  ++keyframes_since_global_ba_;
  // The semantic worker gets every point the new keyframe measures, and the
  // partner keyframe's measurements of the points it helped create.
  hand_off(kf);
  for (const auto& [other, found] : by_partner) hand_off(other, &found);
  cull_redundant_keyframes(kf->id());
}

void MapMaker::cull_redundant_keyframes(KeyFrame::Id newest) {
  if (!options_.culling.enabled) return;
  // Measurements and poses: the map maker, their only writer, reads them
  // without a lock.
  const auto keyframes = map_.keyframes();
  if (keyframes.size() < 3) return;
  std::map<KeyFrame::Id, std::shared_ptr<KeyFrame>> by_id;
  std::map<std::uint64_t, MeasuredLevels> levels;
  for (const auto& kf : keyframes) {
    by_id.emplace(kf->id(), kf);
    MeasuredLevels& measured = levels[kf->id()];
    for (const auto& [id, m] : kf->measurements()) measured.emplace(id, m.level);
  }
  const std::vector<std::uint64_t> culled =
      redundant_keyframes(levels, {keyframes.front()->id(), newest}, options_.culling);
  if (culled.empty()) return;

  for (const std::uint64_t id : culled) {
    const std::shared_ptr<KeyFrame> gone = by_id.at(id);
    by_id.erase(id);
    // The frames tracked against it follow the nearest keyframe left.
    const KeyFrame* parent = nearest_keyframe(by_id, gone->centre_w());
    // Its points' sources and views move to the keyframes still measuring
    // them: for the source the finest level (the sharpest patch), then the
    // newest; for the view the newest, as MapPoint::view() is defined.
    struct Handover {
      std::shared_ptr<MapPoint> point;
      KeyFrame* source = nullptr;
      KeyFrame* view = nullptr;
    };
    std::vector<Handover> handovers;
    for (const auto& [point_id, m] : gone->measurements()) {
      auto p = map_.point(point_id);
      if (!p) continue;
      const bool source_here = p->source().keyframe_id == id, view_here = p->view().keyframe_id == id;
      if (!source_here && !view_here) continue;
      Handover h{p, nullptr, nullptr};
      for (const auto& [other_id, other] : by_id) {
        const auto it = other->measurements().find(point_id);
        if (it == other->measurements().end()) continue;
        if (!h.source || it->second.level <= h.source->measurements().at(point_id).level) h.source = other.get();
        h.view = other.get();  // by_id is in id order: the last is the newest
      }
      handovers.push_back(std::move(h));
    }
    map_.update([&](MapEditor& edit) {
      for (const Handover& h : handovers) {
        if (!h.source) {
          edit.mark_bad(*h.point);  // measured nowhere else
          continue;
        }
        if (h.point->source().keyframe_id == id) {
          const Measurement& m = h.source->measurements().at(h.point->id());
          const PatchSource source{h.source->id(), h.source->pyramid(), m.level, m.pixel};
          edit.set_source(*h.point, *h.source, source,
                          source_geometry(camera_, h.source->T_c_w(), source, h.point->position()));
        }
        if (h.point->view().keyframe_id == id) {
          const Measurement& m = h.view->measurements().at(h.point->id());
          const PatchSource view{h.view->id(), h.view->pyramid(), m.level, m.pixel};
          edit.set_view(*h.point, view, source_geometry(camera_, h.view->T_c_w(), view, h.point->position()));
        }
      }
      edit.cull_keyframe(id, {parent->id(), gone->T_c_w() * parent->T_c_w().inverse()});
    });
    spdlog::debug("keyframe {} (frame {}) culled as redundant: {} points handed on, frames follow keyframe {}", id,
                  gone->frame_index(), handovers.size(), parent->id());
  }
  const auto removed = map_.remove_bad_points();
  std::lock_guard lock(stats_mutex_);
  stats_.keyframes_culled += culled.size();
  stats_.points_removed += removed.size();
}

void MapMaker::remove_outlier_points() {
  const PointCullingOptions culling{.min_searches = options_.outlier_min_searches,
                                    .max_found_ratio = options_.outlier_max_found_ratio,
                                    .grace_keyframes = kSingleViewGraceKeyframes};
  IsLeftOut left_out;
  if (options_.labels.leaves_points_out())
    left_out = [this](const MapPoint& point) { return options_.labels.left_out(point); };
  const std::vector<std::shared_ptr<MapPoint>> outliers =
      points_to_cull(map_.keyframes(), map_.points(), culling, left_out);
  if (!outliers.empty())
    map_.update([&](MapEditor& edit) {
      for (const auto& p : outliers) edit.mark_bad(*p);
    });
  const auto removed = map_.remove_bad_points();
  if (removed.empty()) return;
  std::lock_guard lock(stats_mutex_);
  stats_.points_removed += removed.size();
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
  const MapBaReport ba =
      adjust_map(map_, camera_, BundleAdjuster(options), std::nullopt, {}, ba_point_weight(), &ground_);
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

void MapMaker::count_candidate_done() {
  {
    std::lock_guard lock(done_mutex_);
    ++candidates_done_;
  }
  done_changed_.notify_all();
}

std::size_t MapMaker::candidates_done() const {
  std::lock_guard lock(done_mutex_);
  return candidates_done_;
}

void MapMaker::wait_for_candidates(std::size_t count) const {
  std::unique_lock lock(done_mutex_);
  done_changed_.wait(lock, [&] { return candidates_done_ >= count || !running_; });
}

void MapMaker::process_pending() {
  while (auto candidate = queue_.try_pop()) {
    add_keyframe(std::move(*candidate));
    count_candidate_done();
    if (keyframes_since_global_ba_ >= static_cast<std::size_t>(options_.sync_global_ba_every)) {
      run_global_ba();
      remove_outlier_points();
    }
  }
}

void MapMaker::start() {
  if (thread_.joinable()) return;
  {
    std::lock_guard lock(done_mutex_);
    running_ = true;
  }
  thread_ = std::thread([this] { run(); });
}

void MapMaker::stop() {
  if (!thread_.joinable()) return;
  queue_.close();
  thread_.join();
  {
    std::lock_guard lock(done_mutex_);
    running_ = false;
  }
  done_changed_.notify_all();
}

std::vector<GroundView> MapMaker::ground_views() const {
  std::vector<GroundView> views;
  const auto keyframes = map_.keyframes();
  map_.read([&](const MapView& view) {
    for (const auto& kf : keyframes) {
      GroundView& ground = views.emplace_back(GroundView{kf->T_c_w(), {}});
      for (const auto& [id, m] : kf->measurements())
        if (const auto p = view.point(id); p && !p->is_bad()) ground.points_c.push_back(kf->T_c_w() * p->position());
    }
  });
  return views;
}

void MapMaker::reset() {
  ground_.reset();
  {
    std::lock_guard lock(stats_mutex_);
    stats_.ground.reset();
  }
  map_changed_since_global_ba_ = false;
  keyframes_since_global_ba_ = 0;
}

void MapMaker::run() {
  for (;;) {
    queue_.wait_until([&] { return map_changed_since_global_ba_; });
    if (auto candidate = queue_.try_pop()) {
      add_keyframe(std::move(*candidate));
      count_candidate_done();
      continue;
    }
    if (queue_.closed()) {
      // The run is over: one last global bundle adjustment, as --sync runs
      // one, so the final map (and the trajectory recomposed from it) does
      // not depend on whether the thread happened to be idle at the end.
      if (map_changed_since_global_ba_) {
        run_global_ba();
        remove_outlier_points();
      }
      break;
    }
    if (map_changed_since_global_ba_) {
      run_global_ba();
      remove_outlier_points();
    }
  }
}

PointWeight MapMaker::ba_point_weight() const {
  if (!options_.labels.leaves_points_out()) return {};
  return [this](const MapPoint& point) { return options_.labels.ba_weight(point); };
}

}  // namespace facadeslam
