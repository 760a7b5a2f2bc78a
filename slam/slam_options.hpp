#pragma once
// Options of the whole SLAM system, loaded from configs/slam.yaml (every key
// optional, defaults are PTAM's; unknown keys and bad values are errors).
#include <bitset>
#include <filesystem>
#include <ostream>

#include "core/map/map_point.hpp"
#include "mapmaker/map_maker_options.hpp"
#include "semantics/worker/moving_regions.hpp"
#include "semantics/worker/neighbour_label_fusion.hpp"
#include "slam/init/init_options.hpp"
#include "tracker/tracker_options.hpp"

namespace facadeslam {

// The semantic worker (semantics/worker/) and label-aware tracking, from
// configs/semantics.yaml (load_semantics_options; every key is explained
// there). Off unless a model is given.
struct SemanticsOptions {
  bool enabled = false;
  std::filesystem::path model;  // a .fsmodel (or OpenCV YAML) forest model
  // A model trained on grey photos for grey keyframes (empty: their points
  // stay unlabelled). Same class table and class prior as `model`.
  std::filesystem::path grey_model;
  // How common each class is (any scale): LabelMeFacade train.txt's grid
  // keypoints per class, what the shipped model was trained on.
  ClassVotes class_prior{16751, 176887, 15726, 2864, 20267, 56697, 48167, 32446, 13215};
  // The shipped forest is class-balanced, so its votes ignore how common a
  // class is; each observation's votes are multiplied by prior^weight
  // (0 = the forest's votes as they are, 1 = the full prior).
  double class_prior_weight = 0.5;
  // Each point is also classified in its keyframe shrunk to this scale, the
  // votes added to the full-size ones (0 = not): the 21-pixel patch then
  // sees 84 pixels of facade. street-walk's label accuracy 0.671-0.676 over
  // tracker seeds 1-3 (0.634-0.639 without; 0.5: 0.649-0.667, 0.125: 0.653).
  double context_scale = 0.25;
  // The map's label of each point is its votes fused with those of its this
  // many nearest map points (semantics/worker/neighbour_label_fusion.hpp; 0 =
  // its own votes). street-walk's label accuracy 0.674 -> 0.714 with 15. The
  // tracker keeps weighing points by their own votes (MapPoint::own_label).
  int label_neighbours = 15;
  // ... and a point two keyframes measure at a finite depth is not sky
  // (MapLabelOptions::sky_only_at_infinity).
  bool sky_only_at_infinity = true;
  // How the tracker, bundle adjustment and culling treat a point by its label
  // (core/map/label_policy.hpp). Shipped: car, vegetation, sky and various are
  // unreliable at a vote share of 0.5 or more, cars are moving, and so are
  // points in moving regions (below) unless their step is 0.
  LabelPolicy labels{.unreliable = {.classes = ClassSet{(1u << 2) | (1u << 7) | (1u << 6) | (1u << 0)}},
                     .moving = {.classes = ClassSet{1u << 2}, .regions = true}};
  // Regions the semantic worker finds dense with calls of a moving class
  // (semantics/worker/moving_regions.hpp): the forest calls few of a
  // close-up car's points car one by one, many of its region's. Step 0: no
  // regions.
  semantics::MovingRegionOptions moving_regions;
  // Keyframes waiting for the worker at most (threaded); with more the map
  // maker waits: labels come late rather than memory growing without bound.
  std::size_t max_queued_keyframes = 4;

  // prior^weight per class, scaled so the largest is 1.
  ClassVotes class_weights() const;
  semantics::MapLabelOptions map_labels() const {
    return {.neighbours = label_neighbours, .sky_only_at_infinity = sky_only_at_infinity};
  }
};

// When the map is given up and start-up begins again (ORB-SLAM resets a
// map lost within its first keyframes). A reset discards the map and the
// poses tracked in it: they are in another frame and scale than the next map's.
struct MapResetOptions {
  // A map lost within this many frames of its initialisation, for this many
  // frames in a row: a bad start (wrong scale, too little parallax), not
  // worth keeping. (Age, not keyframes: a slow pan tracks well for seconds
  // on 4 keyframes.)
  int young_map_frames = 30;
  int young_map_lost_frames = 8;
  // Any map lost for this many frames in a row: the camera has left it for
  // good as far as relocalisation can tell; 0 never resets an old map.
  int lost_frames = 90;
};

struct SlamOptions {
  // Start-up's two-view initialisation; its keys live in the config's
  // `mapmaker:` section (init_*), where PTAM users look for them.
  TwoViewOptions initialisation;
  TrackerOptions tracker;
  MapMakerOptions mapmaker;
  SemanticsOptions semantics;
  MapResetOptions map_reset;
  // Synchronous mode: map maker work runs inline at each keyframe, so a run
  // is reproducible bit for bit (set by --sync).
  bool synchronous = false;
  // Threaded mode, replaying files: when the tracker asks for a keyframe it
  // waits (on a condition variable) until the map maker has taken in all but
  // this many of those it asked for. Fed as fast as the tracker goes, a
  // replay otherwise outruns a map maker that shares its cores with other
  // work and tracks on a stale map. The demo's ATE, 5-6 runs each, alone /
  // beside a busy core: free-running 0.43-0.51 / 0.47-1.19 %; 1 (the map
  // maker may be one behind) 0.44-0.63 / 0.43-0.53 %; 0 (each keyframe is
  // in before the next frame) 0.46-0.48 / 0.42-0.47 %, for a third of the
  // threaded frame rate (96-103 instead of 143-156 frames/s on the bench). The map maker's
  // work still overlaps the tracker's between keyframes. -1: never wait, as
  // a live camera cannot (`replay --free-running`).
  int max_keyframes_behind = 0;
};

// Every key is optional (the struct's value is the default) and named as
// its member; unknown keys and values out of range are errors naming the file
// and the key. One table per options struct (slam_options.cpp) reads them
// and writes them back.
SlamOptions load_slam_options(const std::filesystem::path& path);
// Reads configs/semantics.yaml's keys over `defaults`.
SemanticsOptions load_semantics_options(const std::filesystem::path& path, SemanticsOptions defaults = {});
// The settings as YAML the loaders read back, each key under what it means
// (`facadeslam config --dump`).
void write_slam_settings(std::ostream& out, const SlamOptions& options);
void write_semantics_settings(std::ostream& out, const SemanticsOptions& options);

}  // namespace facadeslam
