// facadeslam replay [SEQUENCE]: runs the SLAM system headless over an image
// folder, a TUM rgb.txt list or a video, and writes the trajectory, the
// keyframes, the labelled point cloud, the map and a JSON report.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <shared_mutex>

#include <spdlog/spdlog.h>

#include "apps/cli_support.hpp"
#include "apps/commands.hpp"
#include "core/camera/camera_yaml.hpp"
#include "core/map/map_io.hpp"
#include "core/map/point_cloud_writer.hpp"
#include "core/trajectory/metrics.hpp"
#include "core/trajectory/trajectory_io.hpp"
#include "core/util/error.hpp"
#include "core/util/json.hpp"
#include "core/util/progress.hpp"
#include "sequences/open_sequence.hpp"
#include "slam/system.hpp"

namespace facadeslam::apps {
namespace {

namespace fs = std::filesystem;

// The embedded demo, rendered at set-up (scripts/make-demo).
const fs::path kDemoSequence = "data/demo/sequence";
const fs::path kDefaultOutput = "facadeslam-out";

struct ReplayOptions {
  fs::path sequence, camera, config, out, gt, save_map, load_map;
  bool sync = false;
  std::size_t start = 0, stride = 1, limit = 0;
  std::string on_corrupt = "skip";
};

Eigen::Isometry3d to_isometry(const SE3d& T_w_c) {
  Eigen::Isometry3d iso = Eigen::Isometry3d::Identity();
  iso.linear() = T_w_c.rotation_matrix();
  iso.translation() = T_w_c.translation();
  return iso;
}

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

int run_replay(ReplayOptions o) {
  if (o.sequence.empty()) {
    o.sequence = kDemoSequence;
    if (!fs::exists(o.sequence))
      throw Error(o.sequence.string() + ": the embedded demo is not rendered yet (run scripts/make-demo, or pass a SEQUENCE)");
    if (o.gt.empty() && fs::exists(o.sequence / "groundtruth.txt")) o.gt = o.sequence / "groundtruth.txt";
  }
  if (o.out.empty()) o.out = kDefaultOutput;
  if (o.camera.empty()) {
    const fs::path beside = (fs::is_directory(o.sequence) ? o.sequence : o.sequence.parent_path()) / "camera.yaml";
    if (!fs::exists(beside))
      throw Error(o.sequence.string() + ": no camera given and no camera.yaml beside the sequence (pass --camera)");
    o.camera = beside;
  }
  const Camera camera = load_camera(o.camera);
  SlamOptions slam = o.config.empty() ? SlamOptions{} : load_slam_options(o.config);
  slam.synchronous = o.sync;

  SequenceOptions seq;
  seq.start = o.start;
  seq.stride = o.stride;
  seq.limit = o.limit;
  seq.on_corrupt = corrupt_policy_from_string(o.on_corrupt);
  auto source = open_sequence(o.sequence, seq);
  spdlog::info("replaying {} with camera {} ({})", source->description(), o.camera.string(),
               o.sync ? "synchronous" : "threaded");

  System system(camera, slam);
  if (!o.load_map.empty()) system.load_map(o.load_map);

  Trajectory trajectory;
  std::size_t frames = 0, tracked = 0, lost = 0, relocalisations = 0;
  std::vector<double> t_pyramid, t_coarse, t_fine, t_pose, t_total;
  Progress progress("replay", source->size_hint());
  while (auto frame = source->next()) {
    if (frame->image.cols != camera.width() || frame->image.rows != camera.height())
      fail_file(frame->source, "image is " + std::to_string(frame->image.cols) + "x" + std::to_string(frame->image.rows) +
                                   " but the camera (" + o.camera.string() + ") is " + std::to_string(camera.width()) +
                                   "x" + std::to_string(camera.height()));
    const FrameReport r = system.process(frame->index, frame->timestamp, frame->image);
    ++frames;
    if (r.has_pose) {
      ++tracked;
      trajectory.push_back({r.timestamp, to_isometry(r.T_c_w.inverse())});
    } else if (system.initialised()) {
      ++lost;
    }
    relocalisations += r.status == FrameStatus::relocalised;
    t_pyramid.push_back(r.pyramid_ms);
    t_total.push_back(r.total_ms);
    if (r.status == FrameStatus::tracking || r.status == FrameStatus::relocalised) {
      t_coarse.push_back(r.tracking.timings.coarse_ms);
      t_fine.push_back(r.tracking.timings.fine_ms);
      t_pose.push_back(r.tracking.timings.pose_ms);
    }
    progress.update(frames, to_string(r.status));
  }
  progress.finish();
  if (frames == 0) throw Error(o.sequence.string() + ": the sequence has no frames");
  system.finish();

  fs::create_directories(o.out);
  write_tum_trajectory(o.out / "trajectory.txt", trajectory);
  Trajectory keyframes;
  {
    const auto kfs = system.map().keyframes();
    std::shared_lock lock(system.map().mutex());
    for (const auto& kf : kfs) keyframes.push_back({kf->timestamp(), to_isometry(kf->T_c_w().inverse())});
  }
  write_tum_trajectory(o.out / "keyframes.txt", keyframes);
  const std::size_t cloud_points = write_labelled_point_cloud(o.out / "map.ply", system.map());
  const fs::path map_file = o.save_map.empty() ? o.out / "map.fslmap" : o.save_map;
  save_map(map_file, system.map(), camera);

  const auto stats = system.map_maker_stats();
  Json report = Json::object();
  report["sequence"] = o.sequence.string();
  report["camera"] = o.camera.string();
  report["mode"] = o.sync ? "synchronous" : "threaded";
  report["initialised"] = system.initialised();
  report["frames"] = frames;
  report["frames_tracked"] = tracked;
  report["frames_lost"] = lost;
  report["frames_corrupt_skipped"] = source->stats().frames_skipped_corrupt;
  report["relocalisations"] = relocalisations;
  report["keyframes"] = system.map().keyframe_count();
  report["points"] = cloud_points;
  Json timings = Json::object();
  timings["pyramid_fast"] = timing_summary(t_pyramid);
  timings["coarse"] = timing_summary(t_coarse);
  timings["fine"] = timing_summary(t_fine);
  timings["pose_update"] = timing_summary(t_pose);
  timings["frame_total"] = timing_summary(t_total);
  timings["local_ba_total_ms"] = stats.local_ba_ms;
  timings["global_ba_total_ms"] = stats.global_ba_ms;
  report["timings"] = timings;
  Json mapping = Json::object();
  mapping["points_created"] = stats.points_created;
  mapping["points_removed"] = stats.points_removed;
  mapping["local_ba_runs"] = stats.local_ba_runs;
  mapping["global_ba_runs"] = stats.global_ba_runs;
  mapping["global_ba_aborted"] = stats.global_ba_aborted;
  report["mapping"] = mapping;
  if (!o.gt.empty() && trajectory.size() >= 3) {
    const Trajectory gt = read_trajectory(o.gt);
    const TrajectoryEvaluation e = evaluate_trajectory(gt, trajectory, {});
    report["ate_rmse_m"] = e.ate_rmse_m;
    report["path_length_m"] = e.path_length_m;
    report["ate_percent_of_path"] = e.ate_percent_of_path;
    report["ate_pairs"] = e.pairs;
    report["sim3_scale"] = e.scale;
  }
  write_json(o.out / "report.json", report);

  std::printf("replay: %zu frames, %zu tracked, %zu lost, %zu relocalisations, %zu keyframes, %zu points -> %s\n",
              frames, tracked, lost, relocalisations, system.map().keyframe_count(), cloud_points,
              o.out.string().c_str());
  if (const Json* ate = report.find("ate_rmse_m"))
    std::printf("replay: ATE (Sim3) %.4f m = %.3f %% of the path\n", ate->as_double(),
                report.find("ate_percent_of_path")->as_double());
  if (!system.initialised()) {
    std::fprintf(stderr, "facadeslam: the map was never initialised (not enough parallax?); see %s\n",
                 (o.out / "report.json").string().c_str());
    return kExitNotInitialised;
  }
  return kExitOk;
}

}  // namespace

void add_replay_command(CLI::App& app) {
  auto options = std::make_shared<ReplayOptions>();
  auto* cmd = app.add_subcommand("replay", "Run SLAM headless over an image sequence (default: the embedded demo)");
  cmd->add_option("sequence", options->sequence, "Image folder, TUM rgb.txt list or video file");
  cmd->add_option("--camera", options->camera, "Camera YAML (default: camera.yaml beside the sequence)");
  cmd->add_option("--config", options->config, "SLAM settings YAML (see configs/slam.yaml)");
  cmd->add_option("--out", options->out, "Output folder (default: ./facadeslam-out)");
  cmd->add_option("--gt", options->gt, "Ground-truth TUM trajectory: adds ATE to the report");
  cmd->add_flag("--sync", options->sync, "Run the map maker inline: reproducible results");
  cmd->add_option("--save-map", options->save_map, "Where to write the map (default: OUT/map.fslmap)");
  cmd->add_option("--load-map", options->load_map, "Start from a saved map instead of initialising");
  cmd->add_option("--start", options->start, "Skip this many frames first");
  cmd->add_option("--stride", options->stride, "Use every Nth frame")->check(CLI::PositiveNumber);
  cmd->add_option("--limit", options->limit, "Stop after this many frames (0 = all)");
  cmd->add_option("--on-corrupt", options->on_corrupt, "Corrupt frame policy: skip or stop")
      ->check(CLI::IsMember({"skip", "stop"}));
  cmd->callback([options] {
    const int code = run_replay(*options);
    if (code != kExitOk) throw CLI::RuntimeError(code);
  });
}

}  // namespace facadeslam::apps
