#pragma once
// Options of the whole SLAM system, loaded from configs/slam.yaml (every key
// optional, defaults are PTAM's; unknown keys and bad values are errors).
#include <filesystem>

#include "mapmaker/mapping/map_maker_options.hpp"
#include "tracker/tracking/tracker_options.hpp"

namespace facadeslam {

struct SlamOptions {
  TrackerOptions tracker;
  MapMakerOptions mapmaker;
  // Synchronous mode: map maker work runs inline at each keyframe, so a run
  // is reproducible bit for bit (set by --sync).
  bool synchronous = false;
};

SlamOptions load_slam_options(const std::filesystem::path& path);

}  // namespace facadeslam
