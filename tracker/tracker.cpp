#include "tracker/tracker.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <unordered_map>
#include <utility>

#include <spdlog/spdlog.h>

#include "core/image/small_blurry_image.hpp"
#include "core/util/angles.hpp"
#include "core/util/stopwatch.hpp"

namespace facadeslam {

const char* to_string(TrackingQuality quality) {
  switch (quality) {
    case TrackingQuality::good: return "good";
    case TrackingQuality::dodgy: return "dodgy";
    case TrackingQuality::bad: return "bad";
  }
  return "?";
}

namespace {

// Whether tracking result `a` is better than `b`: a better quality, or the
// same with more inliers.
bool better_than(const TrackingResult& a, const TrackingResult& b) {
  if (a.quality != b.quality) return static_cast<int>(a.quality) < static_cast<int>(b.quality);
  return a.fine_found > b.fine_found;
}

// Border (level-0 pixels) a projection must keep so the 8x8 patch at level 0
// fits; coarser levels are checked by the patch search itself.
constexpr double kProjectionBorder = 4.0;

}  // namespace

struct Tracker::Candidate {
  std::size_t point;      // index into the snapshot
  Eigen::Vector2d pixel;  // predicted level-0 position
  Eigen::Matrix2d warp;   // source-level pixel -> current level-0 pixels
  int search_level;
};

Tracker::Tracker(Camera camera, const Map& map, KeyFrameQueue& keyframes, TrackerOptions options)
    : camera_(camera),
      map_(map),
      keyframes_(keyframes),
      options_(options),
      descriptor_relocaliser_(camera_, options_.descriptor_relocaliser) {}

void Tracker::start(const SE3d& T_c_w, std::size_t frame_index, const Eigen::Matrix<double, 6, 1>& velocity) {
  started_ = true;
  last_keyframe_turned_ = false;
  T_c_w_ = T_c_w;
  velocity_ = velocity;
  found_at_keyframe_ = 0;
  lost_frames_ = 0;
  last_keyframe_frame_ = frame_index;
}

void Tracker::reset() {
  started_ = false;
  points_.clear();
  points_revision_ = 0;
  lost_frames_ = 0;
  velocity_.setZero();
  descriptor_relocaliser_.clear();
}

std::vector<Tracker::Candidate> Tracker::project_map(const std::vector<PointSnapshot>& points, const SE3d& T_c_w,
                                                     int* dropped, SearchCounts* counts) const {
  std::vector<Candidate> out, left_out;
  out.reserve(points.size());
  const Eigen::Matrix3d R_c_w = T_c_w.rotation_matrix();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const auto& g = points[i].geometry;
    const Eigen::Vector3d p_c = T_c_w * g.p_w;
    if (p_c.z() <= 1e-6) continue;
    const Eigen::Vector2d px = camera_.project(p_c);
    if (!camera_.in_image(px, kProjectionBorder)) continue;
    if (counts) ++counts->in_view;
    const Eigen::Matrix2d warp = patch::patch_warp(p_c, R_c_w, points[i].view_geometry, camera_);
    const int level = patch::choose_search_level(warp.determinant(), options_.templates);
    if (level < 0) {
      if (counts) ++counts->bad_warp;
      continue;
    }
    // Down-weighted points are searched like any other (pose_measurements
    // gives them their weight); only a weight of 0 leaves them out.
    const bool left = options_.labels.tracking_weight(*points[i].point) <= 0.0;
    (left ? left_out : out).push_back({i, px, warp, level});
  }
  // Labels must never starve the tracker: where the view is mostly of
  // unreliable classes (a tree filling it, or a forest that calls a facade
  // vegetation), the points are searched after all and the robust pose
  // update has the last word.
  if (static_cast<int>(out.size()) < options_.labels.min_reliable_points) {
    out.insert(out.end(), left_out.begin(), left_out.end());
  } else if (dropped) {
    *dropped += static_cast<int>(left_out.size());
  }
  return out;
}

std::vector<PointMeasurement> Tracker::search(const std::vector<PointSnapshot>& points,
                                              const std::vector<Candidate>& candidates, const patch::SearchImage& image,
                                              double radius_level0, int max_points, int& searched,
                                              SearchCounts* counts) const {
  std::vector<PointMeasurement> found;
  found.reserve(
      static_cast<std::size_t>(std::min<std::size_t>(candidates.size(), static_cast<std::size_t>(max_points))));
  searched = 0;
  for (const auto& c : candidates) {
    if (searched >= max_points) break;
    const auto& point = points[c.point].point;
    // project_map chose the level; the template uses it as it is.
    const patch::PatchTemplate tpl =
        patch::make_patch_template_at_level(points[c.point].view, c.warp, c.search_level, options_.templates);
    if (!tpl.valid()) {
      if (counts) ++counts->template_invalid;
      continue;
    }
    ++searched;
    const double radius = std::max(2.0, radius_level0 / ImagePyramid::level_scale(tpl.search_level));
    const patch::PatchSearchResult r = patch::search_patch(tpl, image, c.pixel, radius, options_.search);
    point->count_search(r.found());
    if (r.found()) {
      found.push_back({point, r.level, r.pixel_level0});
    } else if (counts) {
      counts->no_candidate += r.outcome == patch::SearchOutcome::kNoCandidate;
      counts->score_too_high += r.outcome == patch::SearchOutcome::kScoreTooHigh;
      counts->subpixel_failed += r.outcome == patch::SearchOutcome::kSubpixelFailed;
    }
  }
  return found;
}

std::vector<PoseMeasurement> Tracker::pose_measurements(const std::vector<PointSnapshot>& points,
                                                        const std::vector<PointMeasurement>& found,
                                                        int* down_weighted) const {
  // The snapshot's geometry, not the live point's: the map maker may move
  // points while we track, and we must use one consistent copy.
  std::unordered_map<const MapPoint*, const PointGeometry*> geometry;
  geometry.reserve(points.size());
  for (const auto& p : points) geometry.emplace(p.point.get(), &p.geometry);
  std::vector<PoseMeasurement> out;
  out.reserve(found.size());
  for (const auto& m : found) {
    const double weight = options_.labels.tracking_weight(*m.point);
    if (down_weighted && weight < 1.0) ++*down_weighted;
    out.push_back({geometry.at(m.point.get())->p_w, m.pixel, m.level, weight});
  }
  return out;
}

int Tracker::verify_unreliable(PoseUpdateResult& update, std::vector<PoseMeasurement>& measurements,
                               VerifyWhen when) const {
  if (options_.labels.verify_px <= 0.0) return 0;
  // Labels are a prior, geometry the evidence: a down-weighted point that the
  // pose of the rest reprojects within a pixel or two (in its level's pixels)
  // stands still, whatever its class says (a parked car, a tree on a calm
  // day), and its full weight helps the pose: on a street filmed from a car the
  // near parked cars and trees are much of the translation's evidence. Moving
  // things stay down-weighted, as they land far from where the pose puts them.
  // In the fine stage only where the reliable points alone are few: where
  // they are many, a slowly moving thing (a swaying tree) sits within a pixel
  // or two too, and down-weighting it is what makes the pose better
  // (street-dynamic: 0.95 of the label-free ATE with it, 0.76 without).
  int reliable_inliers = 0;
  for (std::size_t i = 0; i < measurements.size(); ++i)
    reliable_inliers += measurements[i].weight >= 1.0 && update.inliers[i];
  if (when == VerifyWhen::few_reliable && reliable_inliers >= options_.labels.min_reliable_points) return 0;
  const double limit_squared = options_.labels.verify_px * options_.labels.verify_px;
  int verified = 0;
  for (std::size_t i = 0; i < measurements.size(); ++i) {
    PoseMeasurement& m = measurements[i];
    // A point of weight 0 (a moving class, searched only because the view
    // has few others) is no inlier of a pose it did not take part in: its
    // reprojection alone decides.
    if (m.weight >= 1.0 || (m.weight > 0.0 && !update.inliers[i])) continue;
    const Eigen::Vector3d p_c = update.T_c_w * m.p_w;
    if (p_c.z() <= options_.pose.min_depth) continue;
    const double scale = ImagePyramid::level_scale(m.level);
    if ((camera_.project(p_c) - m.pixel).squaredNorm() / (scale * scale) > limit_squared) continue;
    m.weight = 1.0;
    ++verified;
  }
  if (verified == 0) return 0;
  PoseUpdateResult again = update_pose(update.T_c_w, measurements, camera_, options_.pose);
  if (again.ok) update = std::move(again);
  return verified;
}

std::vector<PointMeasurement> Tracker::track_from(const SE3d& T_start, const Frame& frame, TrackingResult& result,
                                                  bool coarse) {
  const Stopwatch snapshot_watch;
  map_.refresh_points_snapshot(points_, points_revision_);
  const std::vector<PointSnapshot>& points = points_;
  result.timings.snapshot_ms += snapshot_watch.elapsed_ms();
  // One row index of the frame's corners, shared by every search of both stages.
  const patch::SearchImage image(*frame.pyramid);
  std::mt19937_64 rng(options_.seed * 0x9E3779B97F4A7C15ULL + frame.index);
  SE3d T_c_w = T_start;
  double fine_radius = options_.fine_radius_px;

  // Coarse stage: points at the coarse levels, wide radius.
  if (options_.coarse_stage && coarse) {
    const Stopwatch t0;
    std::vector<Candidate> candidates = project_map(points, T_c_w);
    std::erase_if(candidates, [&](const Candidate& c) { return c.search_level < options_.coarse_min_level; });
    std::shuffle(candidates.begin(), candidates.end(), rng);
    const auto found = search(points, candidates, image, options_.coarse_radius_px, options_.coarse_max_points,
                              result.coarse_searched, nullptr);
    result.coarse_found = static_cast<int>(found.size());
    result.timings.coarse_ms = t0.elapsed_ms();
    if (result.coarse_found >= options_.coarse_min_found) {
      const Stopwatch t1;
      auto measurements = pose_measurements(points, found, nullptr);
      auto update = update_pose(T_c_w, measurements, camera_, options_.pose);
      // The coarse stage has a few dozen points: down-weighting the static
      // ones among them leaves its pose loose (KITTI's snippet lost 7-8
      // frames so), so the static ones are always verified here.
      if (update.ok) verify_unreliable(update, measurements, VerifyWhen::always);
      if (update.ok) {
        T_c_w = update.T_c_w;
        fine_radius = options_.fine_radius_after_coarse_px;
        result.coarse_pose_used = true;
      }
      result.timings.pose_ms += t1.elapsed_ms();
    }
  }

  // Fine stage: all levels, tight radius, from the coarse pose.
  const Stopwatch t0;
  std::vector<Candidate> candidates = project_map(points, T_c_w, &result.points_dropped, &result.fine_counts);
  std::shuffle(candidates.begin(), candidates.end(), rng);
  result.fine_counts.projected = static_cast<int>(candidates.size());
  std::vector<PointMeasurement> found = search(points, candidates, image, fine_radius, options_.fine_max_points,
                                               result.fine_searched, &result.fine_counts);
  result.timings.fine_ms = t0.elapsed_ms();

  const Stopwatch t1;
  std::vector<PointMeasurement> inliers;
  if (static_cast<int>(found.size()) >= 6) {
    auto measurements = pose_measurements(points, found, &result.points_down_weighted);
    auto update = update_pose(T_c_w, measurements, camera_, options_.pose);
    if (update.ok && result.points_down_weighted > 0)
      result.points_verified = verify_unreliable(update, measurements, VerifyWhen::few_reliable);
    if (update.ok) {
      T_c_w = update.T_c_w;
      result.inlier_rms_px = update.inlier_rms_px;
      for (std::size_t i = 0; i < found.size(); ++i)
        if (update.inliers[i]) inliers.push_back(found[i]);
    }
  }
  result.timings.pose_ms += t1.elapsed_ms();
  result.fine_found = static_cast<int>(inliers.size());
  result.fine_counts.outliers = static_cast<int>(found.size() - inliers.size());
  result.T_c_w = T_c_w;

  const double ratio = result.fine_searched > 0 ? static_cast<double>(result.fine_found) / result.fine_searched : 0.0;
  const bool close = result.inlier_rms_px <= options_.max_good_rms_px;
  if (close && (result.fine_found >= options_.good_found ||
                (result.fine_found >= options_.min_found && ratio >= options_.quality_good)))
    result.quality = TrackingQuality::good;
  else if (result.fine_found < options_.min_found || ratio < options_.quality_lost)
    result.quality = TrackingQuality::bad;
  else
    result.quality = TrackingQuality::dodgy;
  return inliers;
}

std::optional<Tracker::TrackedFrame> Tracker::relocalise(const Frame& frame) {
  const Stopwatch t0;
  const cv::Mat sbi = make_small_blurry_image(*frame.pyramid);
  std::vector<KeyFrameSnapshot> keyframes = map_.snapshot_keyframes();
  // Tries a starting pose: accepted only when the normal search from it
  // tracks well (not merely "not bad": a wrong pose that happens to find a
  // few points would send the tracker down a wrong path).
  auto attempt = [&](const SE3d& T_start) -> std::optional<TrackedFrame> {
    TrackingResult result;
    auto inliers = track_from(T_start, frame, result);
    if (result.quality != TrackingQuality::good) return std::nullopt;
    return TrackedFrame{std::move(result), std::move(inliers)};
  };
  auto done = [&](TrackedFrame found, const char* how, KeyFrame::Id id) {
    spdlog::info("frame {}: relocalised ({}) against keyframe {} after {} lost frames", frame.index, how, id,
                 lost_frames_);
    found.result.timings.relocalise_ms = t0.elapsed_ms();
    return std::optional{std::move(found)};
  };
  if (const auto candidate = find_relocalisation_candidate(sbi, keyframes, camera_, options_.relocaliser))
    if (auto found = attempt(candidate->T_c_w))
      return done(std::move(*found), "small blurry image", candidate->keyframe->id());
  if (!options_.descriptor_relocaliser.enabled || keyframes.empty()) return std::nullopt;
  // The keyframes most like the frame, and the newest (where tracking was
  // lost, if it was lost just now) in any case.
  std::vector<KeyFrameSnapshot> ranked = keyframes_by_similarity(sbi, keyframes);
  const auto newest = std::max_element(keyframes.begin(), keyframes.end(), [](const auto& a, const auto& b) {
    return a.keyframe->id() < b.keyframe->id();
  });
  const auto tried = static_cast<std::size_t>(std::max(1, options_.descriptor_relocaliser.max_keyframes));
  if (std::none_of(ranked.begin(), ranked.begin() + static_cast<std::ptrdiff_t>(std::min(tried, ranked.size())),
                   [&](const auto& k) { return k.keyframe == newest->keyframe; }))
    ranked.insert(ranked.begin() + static_cast<std::ptrdiff_t>(std::min(tried - 1, ranked.size())), *newest);
  if (const auto candidate = descriptor_relocaliser_.relocalise(*frame.pyramid, map_, ranked)) {
    spdlog::debug("frame {}: ORB + PnP pose from keyframe {}: {} of {} matches inliers", frame.index,
                  candidate->keyframe->id(), candidate->inliers, candidate->matches);
    if (auto found = attempt(candidate->T_c_w)) return done(std::move(*found), "ORB + PnP", candidate->keyframe->id());
  }
  return std::nullopt;
}

TrackingResult Tracker::track(const Frame& frame) {
  if (!started_) return {};

  // Lost: relocalise, or stay lost.
  auto relocalised = [&](TrackedFrame found) {
    TrackingResult& result = found.result;
    // Relocalised on the first bad frame, the last pose is the previous
    // frame's: the motion between them is the motion model's best guess
    // (a car entering a turn relocalises once, not every frame of it).
    // After a longer loss the motion is unknown.
    if (lost_frames_ == 0)
      velocity_ = (result.T_c_w * T_c_w_.inverse()).log();
    else
      velocity_.setZero();
    lost_frames_ = 0;
    T_c_w_ = result.T_c_w;
    found_at_keyframe_ = std::max(found_at_keyframe_, result.fine_found);
    result.tracked = true;
    result.relocalised = true;
    // A relocalised view may be new (a multi-view set): it may make a keyframe like any well-tracked frame.
    consider_keyframe(frame, result, std::move(found.inliers));
    return result;
  };
  if (lost_frames_ >= options_.lost_frames_before_relocalising) {
    const Stopwatch t0;
    if (auto found = relocalise(frame)) return relocalised(std::move(*found));
    ++lost_frames_;
    TrackingResult result;
    result.timings.relocalise_ms = t0.elapsed_ms();
    return result;
  }

  TrackingResult result;
  const SE3d predicted = SE3d::exp(options_.velocity_decay * velocity_) * T_c_w_;
  auto inliers = track_from(predicted, frame, result);
  // A bad frame, or one whose points sit far from where the pose puts them.
  const auto doubtful = [&](const TrackingResult& r) {
    return r.quality == TrackingQuality::bad || r.inlier_rms_px > options_.max_good_rms_px;
  };
  // A coarse stage of a dozen points over a wide radius can lock on to wrong
  // matches and pull the pose degrees away (kitti00-300 leaving its second
  // turn: 10 of 19 coarse points "found", the pose 3.9 degrees off a
  // prediction that was right to 0.2, and every fine search failing from
  // there): when the fine stage fails from the coarse pose, it is tried
  // again from the prediction, and the better of the two is kept.
  if (options_.retry_from_prediction && result.coarse_pose_used && doubtful(result)) {
    TrackingResult from_prediction;
    auto inliers_from_prediction = track_from(predicted, frame, from_prediction, false);
    if (better_than(from_prediction, result)) {
      from_prediction.coarse_searched = result.coarse_searched;
      from_prediction.coarse_found = result.coarse_found;
      from_prediction.coarse_pose_rejected = true;
      from_prediction.timings.coarse_ms += result.timings.coarse_ms;
      from_prediction.timings.fine_ms += result.timings.fine_ms;
      from_prediction.timings.pose_ms += result.timings.pose_ms;
      result = std::move(from_prediction);
      inliers = std::move(inliers_from_prediction);
    }
  }
  const SE3d correction = result.T_c_w * predicted.inverse();
  result.prediction_error_deg = rad_to_deg(correction.so3().log().norm());
  result.prediction_error_m = (result.T_c_w.inverse().translation() - predicted.inverse().translation()).norm();
  // A first doubtful frame: perhaps the view jumped, and a relocalised pose
  // that tracks well is worth its time.
  if (doubtful(result) && lost_frames_ == 0 && options_.relocalise_on_first_bad_frame)
    if (auto found = relocalise(frame)) return relocalised(std::move(*found));
  if (result.quality == TrackingQuality::bad) {
    // PTAM: the next few frames are still tracked from the motion model (a
    // blurred or briefly occluded frame says little about where the camera
    // went), and only then does relocalisation take over. The bad frame's
    // own pose update is not trusted.
    ++lost_frames_;
    T_c_w_ = predicted;
    velocity_ *= options_.velocity_decay;
    return result;
  }
  velocity_ = (result.T_c_w * T_c_w_.inverse()).log();
  T_c_w_ = result.T_c_w;
  lost_frames_ = 0;
  result.tracked = true;
  // The overlap rule's reference: the most points found since the last
  // keyframe (its new points are found only once the map maker has added
  // them, a frame or more after the request).
  found_at_keyframe_ = std::max(found_at_keyframe_, result.fine_found);

  consider_keyframe(frame, result, std::move(inliers));
  return result;
}

void Tracker::consider_keyframe(const Frame& frame, TrackingResult& result, std::vector<PointMeasurement> inliers) {
  if (const KeyFrameReason reason = wants_keyframe(result, frame.index); reason != KeyFrameReason::none) {
    request_keyframe(frame, result.T_c_w, std::move(inliers), reason);
    result.keyframe_requested = true;
  }
}

Tracker::KeyFrameReason Tracker::wants_keyframe(const TrackingResult& result, std::size_t frame_index) const {
  if (keyframes_.full()) return KeyFrameReason::none;  // the map maker is busy
  const std::size_t frames = frame_index - last_keyframe_frame_;
  // A keyframe near the camera (in units of its scene depth) that looks the
  // same way already covers this view. Near keyframes that all look
  // elsewhere: the camera has turned.
  const Eigen::Vector3d centre = result.T_c_w.inverse().translation();
  const Eigen::Vector3d axis = optical_axis_w(result.T_c_w);
  const double min_cos = std::cos(deg_to_rad(options_.keyframe_min_angle_deg));
  const auto near_by = [&](const KeyFrameSnapshot& kf, double min_distance) {
    return (kf.centre_w() - centre).norm() / std::max(kf.mean_depth, 1e-9) <= min_distance;
  };
  const auto looks_the_same_way = [&](const KeyFrameSnapshot& kf) { return kf.optical_axis_w().dot(axis) >= min_cos; };
  // The keyframes, copied once and only when a rule needs them.
  std::optional<std::vector<KeyFrameSnapshot>> snapshot;
  const auto keyframes = [&]() -> const std::vector<KeyFrameSnapshot>& {
    if (!snapshot) snapshot = map_.snapshot_keyframes();  // ordered by id: the newest last
    return *snapshot;
  };

  // The view is leaving the map (forward motion, a fast turn): a keyframe
  // as soon as the points found fall below a share of those found when the
  // last keyframe was made, even on dodgy tracking, which is what comes
  // next otherwise; but not on a revisit (tracker_options.hpp).
  if (result.quality != TrackingQuality::bad &&
      frames >= static_cast<std::size_t>(options_.keyframe_min_frames_overlap) &&
      result.fine_found < options_.keyframe_min_overlap * found_at_keyframe_) {
    const auto covers = [&](const KeyFrameSnapshot& kf) {
      return near_by(kf, options_.keyframe_min_distance) && looks_the_same_way(kf);
    };
    const auto settled = [&](const KeyFrameSnapshot& newest) {
      return !near_by(newest, options_.keyframe_min_distance) ||
             newest.keyframe->frame_index() + static_cast<std::size_t>(options_.keyframe_revisit_age_frames) <=
                 frame_index;
    };
    const bool revisit = options_.keyframe_overlap_skips_revisits && !keyframes().empty() &&
                         settled(keyframes().back()) && std::any_of(keyframes().begin(), keyframes().end(), covers);
    if (!revisit) return KeyFrameReason::moved;
  }
  if (result.quality != TrackingQuality::good) return KeyFrameReason::none;
  if (frames < static_cast<std::size_t>(std::min(options_.keyframe_min_frames, options_.keyframe_min_frames_turning)))
    return KeyFrameReason::none;
  // After a turn the newest keyframes hold depth-prior points: the first
  // small step away gives them a baseline, so it makes a keyframe sooner.
  const double min_distance =
      options_.keyframe_min_distance * (last_keyframe_turned_ ? options_.keyframe_distance_after_turn : 1.0);
  bool near = false;
  for (const KeyFrameSnapshot& kf : keyframes()) {
    if (!near_by(kf, min_distance)) continue;
    near = true;
    if (looks_the_same_way(kf)) return KeyFrameReason::none;
  }
  if (near)
    return frames >= static_cast<std::size_t>(options_.keyframe_min_frames_turning) ? KeyFrameReason::turned
                                                                                    : KeyFrameReason::none;
  return frames >= static_cast<std::size_t>(options_.keyframe_min_frames) ? KeyFrameReason::moved
                                                                          : KeyFrameReason::none;
}

void Tracker::request_keyframe(const Frame& frame, const SE3d& T_c_w, std::vector<PointMeasurement> measurements,
                               KeyFrameReason reason) {
  KeyFrameCandidate candidate;
  candidate.frame = frame;  // shares the images
  candidate.T_c_w = T_c_w;
  candidate.measurements = std::move(measurements);
  candidate.turned_on_the_spot = reason == KeyFrameReason::turned;
  last_keyframe_turned_ = candidate.turned_on_the_spot;
  found_at_keyframe_ = static_cast<int>(candidate.measurements.size());
  keyframes_.try_push(std::move(candidate));  // room: wants_keyframe asked, and only the map maker takes
  last_keyframe_frame_ = frame.index;
}

}  // namespace facadeslam
