#pragma once
// PTAM's map maker: builds the first map from a two-view initialisation,
// turns the tracker's keyframe candidates into keyframes, grows the map by
// epipolar search, refines it by local bundle adjustment after each keyframe
// and global bundle adjustment when idle, and removes outliers.
//
// Two ways to run it:
// - threaded: start() runs a thread that waits on the keyframe queue (a
//   condition variable, no sleeping); a global BA started while idle is
//   abandoned as soon as a new candidate arrives; stop() joins;
// - synchronous (--sync): the replay loop calls process_pending() right after
//   the tracker, so every run with the same input gives the same map.
#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/image/frame.hpp"
#include "core/map/keyframe_candidate.hpp"
#include "core/map/keyframe_points.hpp"
#include "core/map/map.hpp"
#include "mapmaker/map_ba.hpp"
#include "mapmaker/map_maker_options.hpp"

namespace facadeslam {

// What start-up (slam/initialiser.hpp) found: two frames and the points
// triangulated between them, to become the first two keyframes.
struct InitialViews {
  Frame first, second;
  SE3d T_second_first;                        // maps first-camera points into the second camera
  std::vector<Eigen::Vector3d> points_first;  // in the first camera's frame
  std::vector<Eigen::Vector2d> pixels_first;  // level-0, per point
  std::vector<Eigen::Vector2d> pixels_second;
  double median_parallax_deg = 0.0;
  std::string model;  // which two-view model gave them, for the log
};

struct MapMakerStats {
  std::size_t keyframes_added = 0;
  std::size_t points_created = 0;
  std::size_t points_removed = 0;
  std::size_t keyframes_culled = 0;
  std::size_t local_ba_runs = 0, global_ba_runs = 0, global_ba_aborted = 0;
  double local_ba_ms = 0, global_ba_ms = 0, keyframe_ms = 0;  // totals
  // The ground gauge (ground_gauge.hpp) of the current map, if it has one,
  // and the local BAs in which it held at least one keyframe.
  std::optional<GroundReference> ground;
  std::size_t ground_held_local_ba_runs = 0;
};

class MapMaker {
 public:
  // `new_points` (optional): where each keyframe's new points go once they
  // are in the map, for the semantic worker.
  MapMaker(Camera camera, Map& map, KeyFrameQueue& queue, MapMakerOptions options,
           KeyFramePointsQueue* new_points = nullptr);
  ~MapMaker();
  MapMaker(const MapMaker&) = delete;
  MapMaker& operator=(const MapMaker&) = delete;

  // Builds the initial map (two keyframes, the triangulated points, a global
  // BA). Returns the pose of the second frame, or nothing if too few points
  // survived (the map is left empty). Call before start().
  std::optional<SE3d> initialise(const InitialViews& views);

  // Synchronous mode: handles every queued candidate (and a periodic global BA).
  void process_pending();
  // One global bundle adjustment now (synchronous mode, end of a run).
  void run_global_ba();

  // Threaded mode.
  void start();
  void stop();  // finishes queued candidates, then joins

  // Keyframe candidates taken from the queue and dealt with (made keyframes
  // or refused), since construction. wait_for_candidates(n) blocks until n
  // are, or the thread is not running: a replay of files lets the tracker
  // wait for each keyframe it asks for (SlamOptions::max_keyframes_behind).
  std::size_t candidates_done() const;
  void wait_for_candidates(std::size_t count) const;

  // A map reset (the map is being cleared): forgets the old map's global-BA
  // bookkeeping; statistics run on. Threaded mode: stop() first.
  void reset();

  MapMakerStats stats() const;

 private:
  void run();
  void add_keyframe(KeyFrameCandidate candidate);
  void remove_outlier_points();
  // Culls the keyframes made redundant (keyframe_culling.hpp); never the
  // first (the gauge of every bundle adjustment) nor `newest`.
  void cull_redundant_keyframes(KeyFrame::Id newest);
  void update_depth_stats(KeyFrame& keyframe);
  // Each point's weight in bundle adjustment (LabelPolicy::ba_weight);
  // none when labels are ignored.
  PointWeight ba_point_weight() const;
  // The keyframes `keyframe` searches for new points against, the near
  // partner first, then the far one if any (epipolar_partner.hpp).
  std::vector<std::shared_ptr<KeyFrame>> epipolar_partners(const KeyFrame& keyframe) const;
  // Queues the keyframe's measurements (only those of `only`'s points, if
  // given) for the semantic worker.
  void hand_off(const std::shared_ptr<KeyFrame>& keyframe, const NewPoints* only = nullptr);
  // Each keyframe's pose and measured points in its camera frame (the ground gauge's reference).
  std::vector<GroundView> ground_views() const;

  Camera camera_;
  Map& map_;
  KeyFrameQueue& queue_;
  MapMakerOptions options_;
  KeyFramePointsQueue* new_points_;
  GroundGauge ground_;  // map maker thread only

  std::thread thread_;
  std::atomic<bool> stopping_{false};
  std::atomic<bool> abort_global_ba_{false};
  bool map_changed_since_global_ba_ = false;  // map maker thread only
  std::size_t keyframes_since_global_ba_ = 0;

  mutable std::mutex stats_mutex_;
  MapMakerStats stats_;

  void count_candidate_done();
  mutable std::mutex done_mutex_;
  mutable std::condition_variable done_changed_;
  std::size_t candidates_done_ = 0;  // under done_mutex_
  bool running_ = false;             // under done_mutex_: the thread is between start() and stop()
};

}  // namespace facadeslam
