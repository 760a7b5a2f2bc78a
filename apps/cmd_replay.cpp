// facadeslam replay [SEQUENCE]: runs the SLAM system headless over an image
// folder, a TUM rgb.txt list or a video, and writes the trajectory, the
// keyframes, the labelled point cloud, the map and a JSON report
// (replay/replay_outputs.hpp).
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <spdlog/spdlog.h>

#include "apps/cli_support.hpp"
#include "apps/commands.hpp"
#include "apps/replay/ground_truth_labels.hpp"
#include "apps/replay/replay_log.hpp"
#include "apps/replay/replay_outputs.hpp"
#include "apps/replay/replay_paths.hpp"
#include "apps/replay/replay_render.hpp"
#include "apps/replay/synth_manifest.hpp"
#include "core/camera/camera_yaml.hpp"
#include "core/trajectory/sequence_ground_truth.hpp"
#include "core/util/error.hpp"
#include "core/util/path_checks.hpp"
#include "core/util/interrupt.hpp"
#include "core/util/progress.hpp"
#include "core/util/staged_folder.hpp"
#include "core/util/shipped_files.hpp"
#include "core/util/stopwatch.hpp"
#include "semantics/evaluation/map_label_accuracy.hpp"
#include "sequences/open_sequence.hpp"
#include "slam/system.hpp"

namespace facadeslam::apps {
// Named, so that a unity build can hold every command's Options and run().
namespace replay_command {
namespace {

namespace fs = std::filesystem;

// The embedded demo (rendered at set-up: scripts/make-demo), the shipped
// forests (models/README.md) and the semantic settings, found beside the
// executable wherever it is run from (core/util/shipped_files.hpp).
const fs::path kDemoSequence = "data/demo/sequence";
const fs::path kDefaultOutput = "facadeslam-out";
const fs::path kDefaultSemanticsConfig = "configs/semantics.yaml";
const fs::path kStreetSemanticsConfig = "configs/semantics-street.yaml";  // --semantics street

struct ReplayOptions {
  fs::path sequence, camera, config, out, gt, gt_labels, save_map, load_map;
  bool sync = false;
  bool free_running = false;  // threaded: never wait for the map maker (a live camera's timing)
  std::size_t start = 0, stride = 1, limit = 0, loop = 1;
  std::string on_corrupt = "skip";
  std::string semantics;  // on, off, or empty: as the semantics config says
  fs::path model, grey_model, semantics_config;
  fs::path render;  // empty: no augmented view
  std::size_t render_every = 1;
};

// Semantics are on by default with the shipped model and settings; a config
// or model the user names must exist (the System loads the model before the
// first frame), the defaults may be missing (run from elsewhere: a warning).
SemanticsOptions semantics_options(const ReplayOptions& o) {
  if (o.semantics == "street" && !o.semantics_config.empty())
    throw Error("--semantics street reads the shipped configs/semantics-street.yaml; with --semantics-config " +
                o.semantics_config.string() + " say --semantics on");
  SemanticsOptions semantics;
  semantics.enabled = true;
  const fs::path shipped_config =
      shipped_file(o.semantics == "street" ? kStreetSemanticsConfig : kDefaultSemanticsConfig);
  const bool user_config = !o.semantics_config.empty();
  if (user_config)
    semantics = load_semantics_options(o.semantics_config, semantics);
  else if (path_exists(shipped_config))
    semantics = load_semantics_options(shipped_config, semantics);
  if (!o.semantics.empty()) semantics.enabled = o.semantics != "off";
  if (!o.model.empty()) semantics.model = o.model;
  if (!o.grey_model.empty()) semantics.grey_model = o.grey_model;
  if (!semantics.enabled) return semantics;
  // A copy of the program without its models/ folder: grey sequences stay
  // unlabelled (said at the end of the run), and with no colour model the
  // semantics are off; models the user names must exist.
  if (o.grey_model.empty() && !user_config && !path_exists(semantics.grey_model)) semantics.grey_model.clear();
  if (o.model.empty() && !user_config && !path_exists(semantics.model)) {
    spdlog::warn("no model at {} (pass --model): semantics off",
                 semantics.model.empty() ? shipped_config.string() : semantics.model.string());
    semantics.enabled = false;
  }
  return semantics;
}

// A synthetic sequence's true depth (synth writes depth.txt beside rgb.txt):
// the render's occlusion is scored against it.
fs::path synthetic_depth_list(const fs::path& sequence) {
  const fs::path folder = is_existing_folder(sequence) ? sequence : sequence.parent_path();
  const fs::path list = folder / "depth.txt";
  return path_exists(list) ? list : fs::path();
}

int run_replay(ReplayOptions o) {
  if (o.sequence.empty()) {
    o.sequence = shipped_file(kDemoSequence);
    if (!path_exists(o.sequence))
      throw Error(o.sequence.string() +
                  ": the embedded demo is not rendered yet (run scripts/make-demo, or pass a SEQUENCE)");
    if (o.gt.empty() && path_exists(o.sequence / "groundtruth.txt")) o.gt = o.sequence / "groundtruth.txt";
  }
  if (o.out.empty()) o.out = kDefaultOutput;
  if (o.camera.empty()) {
    const fs::path beside = (is_existing_folder(o.sequence) ? o.sequence : o.sequence.parent_path()) / "camera.yaml";
    if (!path_exists(beside))
      throw Error(o.sequence.string() + ": no camera given and no camera.yaml beside the sequence (pass --camera)");
    o.camera = beside;
  }
  // Every output against every input and the files already there, before
  // anything is read or written (apps/replay/replay_paths.hpp).
  check_replay_paths({o.sequence, o.camera, o.config, o.gt, o.gt_labels, o.load_map, o.model, o.grey_model,
                      o.semantics_config, o.out, o.save_map, o.render});
  const Camera camera = load_camera(o.camera);
  // The ground truth is read before any frame (a run of minutes must not
  // end in "no such file").
  std::optional<SequenceGroundTruth> ground_truth;
  if (!o.gt.empty()) ground_truth.emplace(o.gt);
  if (!o.load_map.empty()) require_file(o.load_map, "a map file (.fslmap) written by replay --save-map");
  // The outputs go to a staging folder beside --out, moved into place at
  // the end (core/util/staged_folder.hpp): a failed or aborted run leaves
  // the previous folder as it was. Made now, so that a bad --out fails
  // before any frame; removed again if anything below fails.
  StagedFolder staged(o.out);
  // --render outside --out is staged the same way.
  std::optional<StagedFolder> staged_render;
  if (!o.render.empty() && !staged.contains(o.render)) staged_render.emplace(o.render);
  if (!o.save_map.empty() && !staged.contains(o.save_map))
    require_creatable_folder(o.save_map.parent_path().empty() ? "." : o.save_map.parent_path());
  // The render folder is checked (and the video opened) before any frame is
  // read: a bad folder is a bad command line, found at once.
  std::unique_ptr<ReplayRender> ar_render;
  if (!o.render.empty()) {
    try {
      // The video plays the rendered frames at 30 frames/s, slower when
      // frames are skipped, so that the motion keeps about its pace.
      const double video_fps = std::clamp(30.0 / static_cast<double>(o.render_every), 5.0, 30.0);
      ar_render = std::make_unique<ReplayRender>(
          ReplayRenderOptions{
              staged_render ? staged_render->path() : staged.staged(o.render), o.render, o.render_every, video_fps,
              "facadeslam replay " + (o.sequence.parent_path().filename() / o.sequence.filename()).string(),
              synthetic_depth_list(o.sequence)},
          camera);
    } catch (const Error& e) {
      throw CLI::ValidationError("--render", e.what());
    }
  }
  SlamOptions slam = o.config.empty() ? SlamOptions{} : load_slam_options(o.config);
  slam.synchronous = o.sync;
  if (o.free_running) slam.max_keyframes_behind = -1;
  slam.semantics = semantics_options(o);

  SequenceOptions seq;
  seq.start = o.start;
  seq.stride = o.stride;
  seq.limit = o.limit;
  seq.loops = o.loop;
  seq.on_corrupt = corrupt_policy_from_string(o.on_corrupt);
  auto source = open_sequence(o.sequence, seq);
  check_synth_manifest(o.sequence);
  // A KITTI ground truth needs a line for the last selected frame (a video's
  // frame count is the container's guess: checked frame by frame only).
  if (ground_truth && source->size_hint() > 0 && detect_sequence_kind(o.sequence) != SequenceKind::video)
    ground_truth->require_frames_up_to(o.start + (source->size_hint() / o.loop - 1) * o.stride);
  spdlog::info("replaying {} with camera {} ({})", source->description(), o.camera.string(),
               o.sync ? "synchronous" : "threaded");

  System system(camera, slam);
  if (!o.load_map.empty()) system.load_map(o.load_map);

  std::optional<GroundTruthLabelFiles> gt_labels;
  if (const fs::path folder = find_ground_truth_labels(o.sequence, o.gt_labels); !folder.empty()) {
    if (slam.semantics.enabled) spdlog::info("ground-truth labels from {}", folder.string());
    gt_labels.emplace(folder);
    gt_labels->require_files_for(source->image_files());
  }

  ReplayLog log;
  Progress progress("replay", source->size_hint());
  const Stopwatch replay_time;
  // Ctrl-C / SIGTERM: stop after the current frame, then finish the map
  // maker's and the worker's queued work and write complete outputs.
  const InterruptGuard interrupts;
  bool interrupted = false;
  while (auto frame = source->next()) {
    if (interrupt_requested()) {
      interrupted = true;
      progress.finish();
      std::fprintf(stderr,
                   "facadeslam: interrupted before frame %zu: finishing the map and writing the outputs "
                   "(Ctrl-C again to abort)\n",
                   frame->index);
      break;
    }
    if (frame->colour.cols != camera.width() || frame->colour.rows != camera.height())
      fail_file(frame->source, "image is " + std::to_string(frame->colour.cols) + "x" +
                                   std::to_string(frame->colour.rows) + " but the camera (" + o.camera.string() +
                                   ") is " + std::to_string(camera.width()) + "x" + std::to_string(camera.height()));
    if (gt_labels) gt_labels->add(*frame);
    // Pass 0's frames only: the later passes' ground truth is pass 0's, repeated.
    if (ground_truth && source->stats().pass_time_offsets_s.size() <= 1)
      ground_truth->add_frame(frame->index, frame->timestamp);
    // The renderer gets its own copy of the image and reads the map only
    // between frames: the System's work is the same with or without it.
    const std::size_t frame_number = log.frames;
    cv::Mat image_to_render;
    if (ar_render && ar_render->wants(frame_number)) {
      image_to_render = frame->colour.clone();
      ar_render->before_tracking(frame_number, system);
    }
    const FrameReport r = system.process(std::move(*frame));
    log.add(r, system.initialised());
    log.sample_resources(system);
    if (ar_render) ar_render->after_tracking(frame_number, r, image_to_render, system);
    progress.update(log.frames, to_string(r.status));
  }
  progress.finish();
  if (log.frames == 0) throw Error(o.sequence.string() + ": the sequence has no frames");
  system.finish();

  const double replay_fps = static_cast<double>(log.frames) / std::max(1e-9, replay_time.elapsed_s());
  ReplayRunInfo info{o.sequence,
                     o.camera,
                     o.sync,
                     slam.semantics.enabled ? slam.semantics.model : fs::path(),
                     slam.semantics.enabled ? slam.semantics.grey_model : fs::path(),
                     {},
                     {}};
  info.interrupted = interrupted;
  if (ground_truth) info.ground_truth = ground_truth->trajectory();
  if (ar_render) info.render = ar_render->finish(replay_fps);
  if (gt_labels && slam.semantics.enabled)
    info.label_accuracy =
        semantics::map_label_accuracy(system.map(), [&](std::size_t index) { return gt_labels->class_ids(index); });
  const ReplayOutputs outputs = write_replay_outputs(
      {staged.path(), o.save_map.empty() ? staged.path() / "map.fslmap" : staged.staged(o.save_map)}, info, log, system,
      source->stats());
  staged.commit();
  if (staged_render) staged_render->commit();
  std::printf(
      "replay: %zu frames, %zu tracked, %zu lost, %zu relocalised, %zu map resets, %zu keyframes, "
      "%zu points -> %s\n",
      log.frames, log.tracked, log.lost, log.relocalisations, system.map_resets(), system.map().keyframe_count(),
      outputs.cloud_points, o.out.string().c_str());
  // Frames the reader skipped are not in the count above: say so.
  if (const std::size_t skipped = source->stats().frames_skipped_corrupt; skipped > 0)
    std::printf("replay: %zu corrupt frames skipped (not counted above)\n", skipped);
  const Json& report = outputs.report;
  if (report.contains("ate_rmse_m")) {
    std::printf("replay: ATE (Sim3) %.4f m = %.3f %% of the path", report["ate_rmse_m"].get<double>(),
                report["ate_percent_of_path"].get<double>());
    if (report.contains("ate_online") && report["ate_online"].contains("ate_percent_of_path"))
      std::printf(" (as tracked: %.3f %%)", report["ate_online"]["ate_percent_of_path"].get<double>());
    std::printf("\n");
  }
  if (report.contains("render") && ar_render)
    std::printf("replay: rendered %.0f frames (%.0f without overlay) at %.1f frames/s -> %s (video: %s)\n",
                report["render"]["frames_rendered"].get<double>(),
                report["render"]["frames_without_overlay"].get<double>(), replay_fps, o.render.string().c_str(),
                ar_render->video_codec().c_str());
  if (info.label_accuracy && info.label_accuracy->accuracy())
    std::printf("replay: label accuracy %.3f over %zu labelled points\n", *info.label_accuracy->accuracy(),
                info.label_accuracy->evaluated);
  if (const auto stats = system.semantic_stats(); stats && stats->grey_keyframes > 0 && !stats->grey_model)
    std::fprintf(stderr,
                 "facadeslam: the images are grey (%zu of %zu labelling jobs) and no grey model was given "
                 "(--grey-model): their points stay unlabelled (--semantics off silences this)\n",
                 stats->grey_keyframes, stats->keyframes);
  if (interrupted) return interrupt_exit_code();
  if (!system.initialised()) {
    std::fprintf(stderr, "facadeslam: the map was never initialised (not enough parallax?); see %s\n",
                 (o.out / "report.json").string().c_str());
    return kExitNotInitialised;
  }
  return kExitOk;
}

}  // namespace
}  // namespace replay_command

void add_replay_command(CLI::App& app) {
  using namespace replay_command;
  auto options = std::make_shared<ReplayOptions>();
  auto* cmd = app.add_subcommand("replay", "Run SLAM headless over an image sequence (default: the embedded demo)");
  cmd->add_option("sequence", options->sequence, "Image folder, TUM rgb.txt list or video file");
  cmd->add_option("--camera", options->camera, "Camera YAML (default: camera.yaml beside the sequence)");
  cmd->add_option("--config", options->config, "SLAM settings YAML (see configs/slam.yaml)");
  cmd->add_option("--out", options->out,
                  "Output folder (default: ./facadeslam-out), replaced as a whole at the end: a new or empty folder, "
                  "or an earlier replay output")
      ->check(kNonEmptyPath);
  cmd->add_option("--gt", options->gt,
                  "Ground-truth trajectory, TUM or KITTI (line i: frame i's pose): adds ATE and KITTI's relative "
                  "errors to the report");
  cmd->add_option("--gt-labels", options->gt_labels,
                  "Folder of ground-truth label PNGs named like the frames (or their names with .png): adds label "
                  "accuracy to the report "
                  "(default: label/ beside a synthetic sequence)");
  cmd->add_flag("--sync", options->sync, "Run the map maker inline: reproducible results");
  cmd->add_flag("--free-running", options->free_running,
                "Threaded: never wait for the map maker, as with a live camera (by default the tracker waits until "
                "the map maker has taken in each keyframe, so a busy machine does not make it track on a stale map)")
      ->excludes("--sync");
  cmd->add_option("--save-map", options->save_map,
                  "Where to write the map (default: OUT/map.fslmap); replaces only a map file")
      ->check(kNonEmptyPath);
  cmd->add_option("--load-map", options->load_map, "Start from a saved map instead of initialising");
  // Ranges checked as numbers: a negative count must not wrap round to 2^64 - 5.
  cmd->add_option("--start", options->start, "Skip this many frames first")->check(CLI::Range(0.0, 1e12));
  cmd->add_option("--stride", options->stride, "Use every Nth frame")->check(CLI::Range(1.0, 1e9));
  cmd->add_option("--limit", options->limit, "Stop after this many frames (0 = all)")->check(CLI::Range(0.0, 1e12));
  cmd->add_option("--loop", options->loop,
                  "Play the (selected) frames this many times, for soak runs; the ground truth repeats with them")
      ->check(CLI::Range(1.0, 1e6));
  cmd->add_option("--on-corrupt", options->on_corrupt, "Corrupt frame policy: skip or stop")
      ->check(CLI::IsMember({"skip", "stop"}));
  cmd->add_option("--semantics", options->semantics,
                  "Label the map with the semantic worker and track label-aware: on, off, or street (on, with the "
                  "models trained on driving video: configs/semantics-street.yaml) (default: on, or as "
                  "--semantics-config says)")
      ->check(CLI::IsMember({"on", "off", "street"}));
  cmd->add_option("--semantics-config", options->semantics_config,
                  "Semantic settings YAML: model, class prior, unreliable classes (default: configs/semantics.yaml)");
  cmd->add_option("--model", options->model, "Forest model for the semantic worker (default: models/default.fsmodel)");
  cmd->add_option("--grey-model", options->grey_model,
                  "Forest model for grey images (a grey camera; `train --grey`; default: models/grey.fsmodel)");
  auto* render_option =
      cmd->add_option("--render", options->render,
                      "Render the augmented view (AR overlay + map view) of the tracked frames into this "
                      "folder: PNG frames, augmented.mp4, contact_sheet.png (replaced as a whole at the end)")
          ->check(kNonEmptyPath);
  cmd->add_option("--render-every", options->render_every, "With --render: render every Nth frame (default 1)")
      ->check(whole_number(1, 1000000))
      ->needs(render_option);
  cmd->callback([options] {
    const int code = run_replay(*options);
    if (code != kExitOk) throw CLI::RuntimeError(code);
  });
}

}  // namespace facadeslam::apps
