#include "apps/replay/replay_outputs.hpp"

#include <algorithm>
#include <map>
#include <optional>

#include <spdlog/spdlog.h>

#include "core/map/map_io.hpp"
#include "core/map/point_cloud_writer.hpp"
#include "core/map/semantic_classes.hpp"
#include "core/trajectory/kitti_relative_error.hpp"
#include "core/trajectory/metrics.hpp"
#include "core/trajectory/top_view.hpp"
#include "core/trajectory/trajectory_io.hpp"
#include "core/util/error.hpp"

namespace facadeslam::apps {
namespace {

Trajectory keyframe_trajectory(const Map& map) {
  Trajectory keyframes;
  for (const KeyFrameSnapshot& kf : map.snapshot_keyframes())
    keyframes.push_back({kf.keyframe->timestamp(), kf.T_c_w.inverse().isometry()});
  return keyframes;
}

// What the semantic worker did, and the labels the map ended with.
Json semantics_summary(const ReplayRunInfo& info, const ReplayLog& log, const System& system) {
  Json out = Json::object();
  const auto stats = system.semantic_stats();
  out["enabled"] = stats.has_value();
  if (!stats) return out;
  out["model"] = info.model.string();
  out["grey_model"] = stats->grey_model ? Json(info.grey_model.string()) : Json();
  std::size_t labelled = 0, unlabelled = 0;
  std::map<std::uint8_t, std::size_t> counts;
  for (const PointSnapshot& p : system.map().snapshot_points()) {
    const SemanticLabel label = p.point->label();
    if (label.label == kUnlabelled) {
      ++unlabelled;
    } else {
      ++labelled;
      ++counts[label.label];
    }
  }
  out["points_labelled"] = labelled;
  out["points_unlabelled"] = unlabelled;
  // Points the tracker left out of the search, and found points it gave a
  // lower weight, for their class; summed over the frames.
  out["points_dropped_by_tracker"] = log.points_dropped;
  out["points_down_weighted_by_tracker"] = log.points_down_weighted;
  // ... of which the fine stage's pose verified as standing still: full weight after all.
  out["points_verified_by_tracker"] = log.points_verified;
  Json classes = Json::object();
  for (const SemanticClass& c : kSemanticClasses) classes[std::string(c.name)] = counts[c.id];
  out["class_counts"] = classes;
  if (info.label_accuracy) {
    const semantics::MapLabelAccuracy& a = *info.label_accuracy;
    out["label_accuracy"] = a.accuracy() ? Json(*a.accuracy()) : Json();
    out["label_accuracy_points"] = a.evaluated;
    Json per_class = Json::object();
    for (const SemanticClass& c : kSemanticClasses)
      if (const auto share = a.class_accuracy(c.id)) per_class[std::string(c.name)] = *share;
    out["label_accuracy_per_class"] = per_class;
    // Rows: true class, columns: label given (class names), points.
    Json confusion = Json::object();
    for (const SemanticClass& t : kSemanticClasses) {
      if (a.per_class_points[t.id] == 0) continue;
      Json row = Json::object();
      for (const SemanticClass& l : kSemanticClasses)
        if (a.confusion[t.id][l.id] > 0) row[std::string(l.name)] = a.confusion[t.id][l.id];
      confusion[std::string(t.name)] = row;
    }
    out["label_confusion"] = confusion;
  }
  out["worker_ms_per_keyframe"] = timing_summary(stats->keyframe_ms);
  double total_ms = 0.0;
  for (const double ms : stats->keyframe_ms) total_ms += ms;
  // Per observation: the worker describes and classifies a point once per
  // keyframe that measures it.
  out["observations_labelled"] = stats->observations_labelled;
  // Keyframes whose image was grey: the grey model labels them, if given.
  out["grey_keyframes"] = stats->grey_keyframes;
  out["worker_us_per_point"] =
      stats->observations_labelled ? 1000.0 * total_ms / static_cast<double>(stats->observations_labelled) : 0.0;
  return out;
}

// The ATE figures of `estimate` into `out` (ate_rmse_m, path_length_m,
// ate_percent_of_path, ate_pairs, sim3_scale), the top view into `plot`
// unless it is empty; the evaluation, for further figures. A few poses on a
// line (a short stretch of straight driving) leave the alignment
// undetermined: `ate_error` then, and the run's outputs still stand.
std::optional<TrajectoryEvaluation> add_ate_figures(Json& out, const Trajectory& gt, const Trajectory& estimate,
                                                    const std::string& file, const std::filesystem::path& plot) {
  try {
    TrajectoryEvaluation e = evaluate_trajectory(gt, estimate, {});
    out["ate_rmse_m"] = e.ate_rmse_m;
    out["path_length_m"] = e.path_length_m;
    out["ate_percent_of_path"] = e.ate_percent_of_path;
    out["ate_pairs"] = e.pairs;
    out["sim3_scale"] = e.scale;
    if (!plot.empty()) save_top_view_png(plot, gt, e);
    return e;
  } catch (const Error& e) {
    spdlog::warn("no ATE for {}: {}", file, e.what());
    out["ate_error"] = std::string(e.what());
    return std::nullopt;
  }
}

// Every map's poses when maps were reset: segments/N/trajectory.txt and
// trajectory_online.txt, N = 1, 2, ... in order, the last being the current
// map's (the same as trajectory.txt). Each has its own scale and origin, so
// each is scored against the ground truth on its own. Returns the report's
// list of segments.
Json write_trajectory_segments(const std::filesystem::path& folder, const System& system, const Trajectory& gt) {
  std::vector<TrajectorySegment> segments = system.earlier_segments();
  segments.push_back({system.final_trajectory(), system.online_trajectory()});
  Json out = Json::array();
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const TrajectorySegment& segment = segments[i];
    const std::filesystem::path dir = folder / std::to_string(i + 1);
    std::filesystem::create_directories(dir);
    write_tum_trajectory(dir / "trajectory.txt", segment.final);
    write_tum_trajectory(dir / "trajectory_online.txt", segment.online);
    const std::string file = (std::filesystem::path("segments") / std::to_string(i + 1) / "trajectory.txt").string();
    Json entry = Json::object();
    entry["file"] = file;
    entry["poses"] = segment.final.size();
    if (!segment.final.empty()) {
      entry["first_timestamp"] = segment.final.front().timestamp;
      entry["last_timestamp"] = segment.final.back().timestamp;
    }
    if (!gt.empty() && segment.final.size() >= 3) add_ate_figures(entry, gt, segment.final, file, {});
    out.push_back(entry);
  }
  return out;
}

Json mapping_summary(const MapMakerStats& stats) {
  Json mapping = Json::object();
  mapping["points_created"] = stats.points_created;
  mapping["points_removed"] = stats.points_removed;
  mapping["keyframes_added"] = stats.keyframes_added;
  mapping["keyframes_culled"] = stats.keyframes_culled;
  mapping["local_ba_runs"] = stats.local_ba_runs;
  mapping["global_ba_runs"] = stats.global_ba_runs;
  mapping["global_ba_aborted"] = stats.global_ba_aborted;
  // The camera's height above the road holding the scale (a vehicle's
  // camera), in map units, or null.
  Json ground = nullptr;
  if (stats.ground) {
    ground = Json::object();
    ground["height"] = stats.ground->height;
    ground["normal_in_camera"] = {stats.ground->normal_c.x(), stats.ground->normal_c.y(), stats.ground->normal_c.z()};
    ground["reference_points"] = stats.ground->inliers;
    ground["local_ba_runs_held"] = stats.ground_held_local_ba_runs;
  }
  mapping["ground_gauge"] = ground;
  return mapping;
}

}  // namespace

ReplayOutputs write_replay_outputs(const ReplayOutputPaths& paths, const ReplayRunInfo& info, const ReplayLog& log,
                                   const System& system, const ReadStats& read_stats) {
  std::filesystem::create_directories(paths.out);
  // trajectory.txt from the final map (each frame recomposed on its
  // reference keyframe after the last bundle adjustment); the poses as
  // tracked, with the jumps a later map correction leaves, beside it.
  const Trajectory trajectory = system.final_trajectory();
  const Trajectory online = system.online_trajectory();
  write_tum_trajectory(paths.out / "trajectory.txt", trajectory);
  write_tum_trajectory(paths.out / "trajectory_online.txt", online);
  write_tum_trajectory(paths.out / "keyframes.txt", keyframe_trajectory(system.map()));
  const std::size_t cloud_points = write_labelled_point_cloud(paths.out / "map.ply", system.map());
  save_map(paths.map_file, system.map(), system.camera());

  const auto stats = system.map_maker_stats();
  Json report = Json::object();
  report["sequence"] = info.sequence.string();
  report["camera"] = info.camera_file.string();
  report["mode"] = info.synchronous ? "synchronous" : "threaded";
  report["initialised"] = system.initialised();
  report["interrupted"] = info.interrupted;
  report["frames"] = log.frames;
  // replay --loop: how many times the frames were played (1 without).
  report["passes"] = std::max<std::size_t>(1, read_stats.pass_time_offsets_s.size());
  report["frames_tracked"] = log.tracked;
  report["frames_lost"] = log.lost;
  report["frames_corrupt_skipped"] = read_stats.frames_skipped_corrupt;
  report["relocalisations"] = log.relocalisations;
  report["frames_after_initialisation"] = log.after_initialisation;
  report["tracked_share_after_initialisation"] =
      log.after_initialisation
          ? static_cast<double>(log.tracked_after_initialisation) / static_cast<double>(log.after_initialisation)
          : 0.0;
  // Maps given up (lost early or for long) and the tracked poses dropped
  // with them: the trajectories hold the last map's frames only.
  report["map_resets"] = system.map_resets();
  report["keyframes"] = system.map().keyframe_count();
  report["points"] = cloud_points;
  Json timings = log.timings();
  timings["local_ba_total_ms"] = stats.local_ba_ms;
  timings["global_ba_total_ms"] = stats.global_ba_ms;
  report["timings"] = timings;
  report["resources"] = log.resources_json();
  report["mapping"] = mapping_summary(stats);
  report["semantics"] = semantics_summary(info, log, system);
  if (info.render) report["render"] = *info.render;
  if (!info.ground_truth.empty() && trajectory.size() >= 3) {
    // trajectory.txt's figures at the top level (the names report.json has
    // always had), the online trajectory's under the same names in ate_online.
    // A looped replay's ground truth repeats with the frames (looping_source.hpp).
    const Trajectory gt = repeat_trajectory(info.ground_truth, read_stats.pass_time_offsets_s);
    if (const auto e = add_ate_figures(report, gt, trajectory, "trajectory.txt", paths.out / "trajectory.png")) {
      // On the Sim(3)-aligned trajectory.txt, as the ATE; "no_segments" below 100 m of path.
      Json kitti = to_json(kitti_relative_error_after_alignment(gt, trajectory, *e));
      kitti["estimate_aligned_with"] = "sim3";
      report["kitti_relative"] = kitti;
    }
    Json ate_online = Json::object();
    add_ate_figures(ate_online, gt, online, "trajectory_online.txt", {});
    report["ate_online"] = ate_online;
  }
  if (!system.earlier_segments().empty()) {
    const Trajectory gt =
        info.ground_truth.empty() ? Trajectory{} : repeat_trajectory(info.ground_truth, read_stats.pass_time_offsets_s);
    report["trajectory_segments"] = write_trajectory_segments(paths.out / "segments", system, gt);
  }
  write_json(paths.out / "report.json", report);
  return {report, cloud_points};
}

}  // namespace facadeslam::apps
