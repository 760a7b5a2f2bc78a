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
#include <functional>
#include <memory>
#include <thread>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/map/keyframe_queue.hpp"
#include "core/map/map.hpp"
#include "mapmaker/init/two_view_result.hpp"
#include "mapmaker/mapping/map_maker_options.hpp"

namespace facadeslam {

// A frame as the map maker needs it for initialisation.
struct MapMakerFrame {
  std::size_t index = 0;
  double timestamp = 0.0;
  std::shared_ptr<const ImagePyramid> pyramid;
  cv::Mat colour;
  cv::Mat small_blurred;  // for relocalisation
};

struct MapMakerStats {
  std::size_t keyframes_added = 0;
  std::size_t points_created = 0;
  std::size_t points_removed = 0;
  std::size_t local_ba_runs = 0, global_ba_runs = 0, global_ba_aborted = 0;
  double local_ba_ms = 0, global_ba_ms = 0, keyframe_ms = 0;  // totals
};

class MapMaker {
 public:
  // Called with each keyframe's new points once they are in the map (the
  // semantic worker's input). Runs on the map maker's thread.
  using NewPointsCallback =
      std::function<void(const std::shared_ptr<KeyFrame>&, const std::vector<std::shared_ptr<MapPoint>>&)>;

  MapMaker(Camera camera, Map& map, KeyFrameQueue& queue, MapMakerOptions options);
  ~MapMaker();
  MapMaker(const MapMaker&) = delete;
  MapMaker& operator=(const MapMaker&) = delete;

  void set_new_points_callback(NewPointsCallback callback) { on_new_points_ = std::move(callback); }

  // Builds the initial map (two keyframes, the triangulated points, a global
  // BA). Returns the pose of the second frame, or nothing if too few points
  // survived (the map is left empty). Call before start().
  std::optional<SE3d> initialise(const TwoViewResult& result, const MapMakerFrame& first,
                                 const MapMakerFrame& second);

  // Synchronous mode: handles every queued candidate (and a periodic global BA).
  void process_pending();
  // One global bundle adjustment now (synchronous mode, end of a run).
  void run_global_ba();

  // Threaded mode.
  void start();
  void stop();  // finishes queued candidates, then joins

  MapMakerStats stats() const;

 private:
  void run();
  void add_keyframe(KeyFrameCandidate candidate);
  void remove_outlier_points();
  void update_depth_stats(KeyFrame& keyframe);
  // The keyframe `keyframe` searches for new points against (epipolar_partner.hpp).
  std::shared_ptr<KeyFrame> epipolar_partner(const KeyFrame& keyframe) const;
  void publish_new_points(const std::shared_ptr<KeyFrame>& keyframe, std::vector<std::shared_ptr<MapPoint>> points);

  Camera camera_;
  Map& map_;
  KeyFrameQueue& queue_;
  MapMakerOptions options_;
  NewPointsCallback on_new_points_;

  std::thread thread_;
  std::atomic<bool> stopping_{false};
  std::atomic<bool> abort_global_ba_{false};
  bool map_changed_since_global_ba_ = false;  // map maker thread only
  std::size_t keyframes_since_global_ba_ = 0;

  mutable std::mutex stats_mutex_;
  MapMakerStats stats_;
};

}  // namespace facadeslam
