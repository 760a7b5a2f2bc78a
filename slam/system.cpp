#include "slam/system.hpp"

#include <spdlog/spdlog.h>

#include "core/map/map_io.hpp"
#include "core/util/error.hpp"
#include "core/util/stopwatch.hpp"
#include "semantics/text.hpp"
#include "semantics/worker/neighbour_label_fusion.hpp"

namespace facadeslam {

const char* to_string(FrameStatus status) {
  switch (status) {
    case FrameStatus::initialising: return "initialising";
    case FrameStatus::initialised: return "initialised";
    case FrameStatus::tracking: return "tracking";
    case FrameStatus::lost: return "lost";
    case FrameStatus::relocalised: return "relocalised";
  }
  return "?";
}

namespace {

// The worker for `options`, or none. The model is loaded here, before any
// frame: a missing or foreign model fails the run before it starts.
std::unique_ptr<semantics::SemanticWorker> make_worker(const SemanticsOptions& options, KeyFramePointsQueue& queue,
                                                       const Map& map) {
  if (!options.enabled) return nullptr;
  // Colour keyframes go to `model`, grey ones to `grey_model`: a forest
  // trained on the other kind labels without any error, badly.
  using semantics::ModelImages;
  const auto load = [](const std::filesystem::path& path, ModelImages wanted, const char* option) {
    semantics::ForestModel model = semantics::load_forest_model(path);
    if (model.classes != semantics::labelmefacade_class_table())
      fail_file(path, "a model for LabelMeFacade's nine classes (the map's class table)");
    if (model.images != ModelImages::unknown && model.images != wanted)
      fail_file(path,
                semantics::cat("a model trained on ", semantics::model_images_name(model.images), " images, given as ",
                               option, ", which labels ", semantics::model_images_name(wanted), " keyframes",
                               wanted == ModelImages::colour ? " (grey models go to --grey-model)"
                                                             : " (colour models go to --model)"));
    return model;
  };
  auto worker = std::make_unique<semantics::SemanticWorker>(load(options.model, ModelImages::colour, "the model"),
                                                            queue, options.class_weights());
  if (!options.grey_model.empty())
    worker->use_grey_model(load(options.grey_model, ModelImages::grey, "the grey model"));
  worker->use_context_scale(options.context_scale);
  worker->use_moving_regions(options.moving_regions, options.labels.moving.classes);
  worker->use_map_labels(map, options.map_labels());
  return worker;
}

// With labels coming, the tracker, bundle adjustment and culling share one
// label policy; moving regions count only where the worker detects them.
SlamOptions with_label_aware_tracking(SlamOptions options) {
  if (!options.semantics.enabled) return options;
  LabelPolicy labels = options.semantics.labels;
  labels.moving.regions = labels.moving.regions && options.semantics.moving_regions.step > 0;
  options.tracker.labels = options.mapmaker.labels = labels;
  return options;
}

}  // namespace

System::System(Camera camera, SlamOptions options)
    : camera_(camera),
      options_(with_label_aware_tracking(std::move(options))),
      // Bounded hand-offs: a busy map maker gets no keyframe candidates, a
      // busy worker holds the map maker up. Inline (--sync) each is emptied
      // every frame by the one thread, which must never wait on itself.
      queue_(options_.tracker.keyframe_max_queue),
      new_points_(options_.synchronous ? KeyFramePointsQueue::kUnbounded : options_.semantics.max_queued_keyframes),
      worker_(make_worker(options_.semantics, new_points_, map_)),
      map_maker_(camera_, map_, queue_, options_.mapmaker, worker_ ? &new_points_ : nullptr),
      tracker_(camera_, map_, queue_, options_.tracker),
      initialiser_(camera_, options_.initialisation, map_maker_) {}

System::~System() {
  map_maker_.stop();
  if (worker_) worker_->stop();
}

std::optional<semantics::SemanticWorkerStats> System::semantic_stats() const {
  if (!worker_) return std::nullopt;
  return worker_->stats();
}

void System::start_tracking(const SE3d& T_c_w, std::size_t frame_index, const Eigen::Matrix<double, 6, 1>& velocity) {
  initialised_ = true;
  initialised_at_ = frame_index;
  tracker_.start(T_c_w, frame_index, velocity);
  keyframes_requested_ = map_maker_.candidates_done();
  if (!options_.synchronous) {
    map_maker_.start();
    if (worker_) worker_->start();
  }
}

void System::load_map(const std::filesystem::path& path) {
  facadeslam::load_map(path, map_, &camera_);
  if (map_.keyframe_count() < 2 || map_.point_count() == 0)
    fail_file(path, "the map has no keyframes or points to track against");
  // The file keeps each point's own votes; its labels are those fused with
  // the neighbours', as when the map was made.
  semantics::fuse_labels_with_neighbours(map_, options_.semantics.map_labels());
  // Nothing is known of the camera yet: the tracker starts lost and relocalises.
  start_tracking(map_.snapshot_keyframes().back().T_c_w, 0, Eigen::Matrix<double, 6, 1>::Zero());
  tracker_.mark_lost();
  map_loaded_ = true;
}

FrameReport System::process(Frame frame) {
  const Stopwatch total;
  FrameReport report;
  report.index = frame.index;
  report.timestamp = frame.timestamp;
  frame.pyramid = std::make_shared<const ImagePyramid>(frame.colour, options_.tracker.pyramid);
  report.pyramid_ms = total.elapsed_ms();

  if (!initialised_) {
    report.status = FrameStatus::initialising;
    if (const auto start = initialiser_.add_frame(frame)) {
      start_tracking(start->T_c_w, frame.index, start->velocity);
      FrameReport reference;  // the first keyframe's frame: in the trajectories too, as ORB-SLAM writes it
      reference.index = start->reference_index;
      reference.timestamp = start->reference_timestamp;
      record_pose(reference);
      report.initial_reference = std::pair{reference.index, reference.timestamp};
      report.status = FrameStatus::initialised;
      report.has_pose = true;
      report.T_c_w = start->T_c_w;
      record_pose(report);  // the map maker made a keyframe of this very frame: the nearest
    }
  } else {
    report.tracking = tracker_.track(frame);
    report.has_pose = report.tracking.tracked;
    report.T_c_w = report.tracking.T_c_w;
    report.status = !report.tracking.tracked      ? FrameStatus::lost
                    : report.tracking.relocalised ? FrameStatus::relocalised
                                                  : FrameStatus::tracking;
    // Before the map maker's turn in --sync: the keyframe poses are then the
    // ones the tracker measured against.
    if (report.has_pose) record_pose(report);
    if (options_.synchronous) {
      map_maker_.process_pending();
      if (worker_) worker_->process_pending();
    } else if (report.tracking.keyframe_requested && options_.max_keyframes_behind >= 0) {
      // With 0 (the default) the keyframe just asked for is in before the
      // next frame; with 1 it is taken in while the next frames are tracked
      // and only the one before must be in by now.
      ++keyframes_requested_;
      const auto behind = static_cast<std::size_t>(options_.max_keyframes_behind);
      if (keyframes_requested_ > behind) map_maker_.wait_for_candidates(keyframes_requested_ - behind);
    }
    log_tracking(report);
    if (!report.has_pose && should_reset(frame.index)) {
      reset_map(frame);
      report.map_reset = true;
    }
  }
  report.total_ms = total.elapsed_ms();
  return report;
}

bool System::should_reset(std::size_t frame_index) const {
  if (map_loaded_) return false;
  const int lost = tracker_.lost_frames();
  const MapResetOptions& r = options_.map_reset;
  const auto lost_since = static_cast<std::ptrdiff_t>(frame_index) - lost + 1;
  const bool young = lost_since - static_cast<std::ptrdiff_t>(initialised_at_) <= r.young_map_frames;
  if (young && lost >= r.young_map_lost_frames) return true;
  return r.lost_frames > 0 && lost >= r.lost_frames;
}

void System::reset_map(const Frame& frame) {
  spdlog::info("frame {}: map reset after {} lost frames ({} keyframes, {} points): initialising again", frame.index,
               tracker_.lost_frames(), map_.keyframe_count(), map_.point_count());
  // The threads first: nothing may touch the map while it is emptied. What
  // they had queued belongs to the old map.
  queue_.clear();
  new_points_.clear();
  if (!options_.synchronous) {
    map_maker_.stop();
    if (worker_) worker_->stop();
  }
  // The threads are stopped: the map holds still for its poses to be kept.
  if (trajectory_.size() > 0) earlier_segments_.push_back({final_trajectory(), online_trajectory()});
  queue_.reopen();
  new_points_.reopen();
  map_.clear();
  map_maker_.reset();
  tracker_.reset();
  trajectory_.clear();
  initialiser_.reset();
  initialiser_.add_frame(frame);  // the new reference
  initialised_ = false;
  ++map_resets_;
}

void System::record_pose(const FrameReport& report) {
  // The reference is the keyframe nearest the camera. Tried first, in the
  // tracker: the keyframe that made, or last measured (MapPoint::view), most
  // of the points found, after ORB-SLAM's keyframe sharing most points. Both
  // tie long runs of frames to the first keyframe (it makes the initial
  // map's many points and stays their view), which bundle adjustment holds
  // fixed, so those frames never move with the map corrected around them:
  // the demo's --sync final ATE was 0.92 and 1.08 % against 0.87 % as
  // tracked; with the nearest keyframe 0.49 %. Threaded,
  // the map maker may have moved the keyframe since the tracker's snapshot
  // (one BA step at most): its pose now is the nearest to the one the frame
  // was measured against that can be had without the tracker copying the
  // keyframes every frame.
  const Eigen::Vector3d centre = report.T_c_w.inverse().translation();
  const auto reference = map_.read([&](const MapView& view) -> std::optional<std::pair<KeyFrame::Id, SE3d>> {
    const KeyFrame* nearest = nearest_keyframe(view.keyframes(), centre);
    if (!nearest) return std::nullopt;
    return std::pair{nearest->id(), nearest->T_c_w()};
  });
  if (reference)
    trajectory_.add(report.index, report.timestamp, report.T_c_w, reference->first, reference->second);
  else
    trajectory_.add_online(report.index, report.timestamp, report.T_c_w);
}

Trajectory System::final_trajectory() const {
  const RelativeTrajectory::Recomposed final =
      trajectory_.recompose(map_.snapshot_keyframes(), map_.culled_keyframes());
  if (final.fallbacks)
    spdlog::warn("final trajectory: {} of {} frames kept their tracked pose (reference keyframe no longer in the map)",
                 final.fallbacks, trajectory_.size());
  return final.trajectory;
}

void System::log_tracking(const FrameReport& report) const {
  if (!spdlog::should_log(spdlog::level::debug)) return;
  const TrackingResult& t = report.tracking;
  const SearchCounts& c = t.fine_counts;
  spdlog::debug(
      "frame {}: {} ({}), coarse {}/{}, fine {}/{} of {} projected ({} in view, {} bad warp, {} dropped; "
      "no template {}, no corner {}, zmssd {}, sub-pixel {}, outliers {}), rms {:.2f} px, "
      "predicted within {:.2f} deg {:.3f}, {:.2f}+{:.2f}+{:.2f}+{:.2f} ms{}{}",
      report.index, to_string(report.status), to_string(t.quality), t.coarse_found, t.coarse_searched, t.fine_found,
      t.fine_searched, c.projected, c.in_view, c.bad_warp, t.points_dropped, c.template_invalid, c.no_candidate,
      c.score_too_high, c.subpixel_failed, c.outliers, t.inlier_rms_px, t.prediction_error_deg, t.prediction_error_m,
      report.pyramid_ms, t.timings.coarse_ms, t.timings.fine_ms, t.timings.pose_ms,
      t.coarse_pose_rejected ? ", coarse pose rejected" : "", t.keyframe_requested ? ", keyframe requested" : "");
}

void System::finish() {
  if (options_.synchronous) {
    map_maker_.process_pending();
    if (initialised_) map_maker_.run_global_ba();
    if (worker_) worker_->process_pending();
  } else {
    map_maker_.stop();
    if (worker_) worker_->stop();
  }
  // The final bundle adjustment has moved the points since the last fusion.
  if (worker_) worker_->fuse();
}

}  // namespace facadeslam
