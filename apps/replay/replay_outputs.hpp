#pragma once
// Everything a replay leaves in its output folder: trajectory.txt (every
// frame with a pose, TUM, recomposed from the final map),
// trajectory_online.txt (the same frames' poses as tracked), keyframes.txt
// (TUM), map.ply (labelled point cloud), the map file, report.json and, with
// ground truth, trajectory.png (top view of trajectory.txt against it). Each
// file is written atomically.
#include <filesystem>
#include <optional>

#include "apps/replay/replay_log.hpp"
#include "core/camera/camera.hpp"
#include "core/trajectory/trajectory.hpp"
#include "core/util/json.hpp"
#include "semantics/evaluation/map_label_accuracy.hpp"
#include "sequences/frame_source.hpp"
#include "slam/system.hpp"

namespace facadeslam::apps {

struct ReplayOutputPaths {
  std::filesystem::path out;       // output folder
  std::filesystem::path map_file;  // where the map goes
};

struct ReplayRunInfo {
  std::filesystem::path sequence, camera_file;
  bool synchronous = false;
  std::filesystem::path model;       // empty: semantics off
  std::filesystem::path grey_model;  // empty: none (grey keyframes stay unlabelled)
  // Against ground-truth label images, when the sequence has them.
  std::optional<semantics::MapLabelAccuracy> label_accuracy;
  // With --render: what was rendered (apps/replay/replay_render.hpp).
  std::optional<Json> render;
  bool interrupted = false;  // stopped early by Ctrl-C / SIGTERM: the outputs cover the frames before
  // replay --gt (core/trajectory/sequence_ground_truth.hpp), of one pass; empty without.
  Trajectory ground_truth{};
};

struct ReplayOutputs {
  Json report;                   // as written to report.json
  std::size_t cloud_points = 0;  // points written to map.ply
};

// Writes the files.
ReplayOutputs write_replay_outputs(const ReplayOutputPaths& paths, const ReplayRunInfo& info, const ReplayLog& log,
                                   const System& system, const ReadStats& read_stats);

}  // namespace facadeslam::apps
