#pragma once
// Options of the whole SLAM system, loaded from configs/slam.yaml (every key
// optional, defaults are PTAM's; unknown keys and bad values are errors).
#include <filesystem>

#include "mapmaker/map_maker_options.hpp"
#include "slam/init/init_options.hpp"
#include "tracker/tracker_options.hpp"

namespace facadeslam {

// The semantic worker (semantics/worker/): off unless a model is given.
struct SemanticsOptions {
  bool enabled = false;
  std::filesystem::path model;  // a .fsmodel (or OpenCV YAML) forest model
};

struct SlamOptions {
  // Start-up's two-view initialisation; its keys live in the config's
  // `mapmaker:` section (init_*), where PTAM users look for them.
  TwoViewOptions initialisation;
  TrackerOptions tracker;
  MapMakerOptions mapmaker;
  SemanticsOptions semantics;
  // Synchronous mode: map maker work runs inline at each keyframe, so a run
  // is reproducible bit for bit (set by --sync).
  bool synchronous = false;
};

SlamOptions load_slam_options(const std::filesystem::path& path);

}  // namespace facadeslam
