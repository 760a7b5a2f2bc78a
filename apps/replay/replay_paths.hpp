#pragma once
// Every path of a replay, checked before any frame (core/util/output_policy.hpp):
// --out replaces only an earlier replay output, --save-map only a map,
// --render only an earlier render folder; no output is or holds an input
// (`replay SEQ --out SEQ` is refused), and no two outputs collide
// (`--save-map OUT/report.json`, `--save-map OUT`).
#include <filesystem>

namespace facadeslam::apps {

struct ReplayPaths {
  std::filesystem::path sequence, camera, config, gt, gt_labels, load_map, model, grey_model, semantics_config;
  std::filesystem::path out, save_map, render;
};

// An Error naming the path and the option at the first rule broken.
void check_replay_paths(const ReplayPaths& paths);

}  // namespace facadeslam::apps
