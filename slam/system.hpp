#pragma once
// The SLAM system behind `facadeslam replay`: one Map shared by the tracker
// (run on the caller's thread, frame by frame), the map maker and the
// semantic worker (each on its own thread, or inline in synchronous mode).
//
// Before a map exists the system starts up automatically (initialiser.hpp):
// it tracks the corners of a reference frame until a frame with enough
// parallax gives a reconstruction, which the map maker turns into the first
// two keyframes. With semantics on, the semantic worker labels every
// keyframe's new points (its own thread, or inline after the map maker).
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/image/frame.hpp"
#include "core/map/keyframe_candidate.hpp"
#include "core/map/keyframe_points.hpp"
#include "core/map/map.hpp"
#include "core/trajectory/trajectory.hpp"
#include "mapmaker/map_maker.hpp"
#include "slam/initialiser.hpp"
#include "slam/relative_trajectory.hpp"
#include "slam/slam_options.hpp"
#include "semantics/worker/semantic_worker.hpp"
#include "tracker/tracker.hpp"

namespace facadeslam {

enum class FrameStatus { initialising, initialised, tracking, lost, relocalised };
const char* to_string(FrameStatus status);

struct FrameReport {
  std::size_t index = 0;
  double timestamp = 0.0;
  FrameStatus status = FrameStatus::initialising;
  bool has_pose = false;
  SE3d T_c_w;
  TrackingResult tracking;
  // On the frame that initialised: the reference frame it was initialised
  // against (index, timestamp), the first keyframe, whose pose (the world
  // origin) is known only now. The trajectories have it.
  std::optional<std::pair<std::size_t, double>> initial_reference;
  // The map was given up on this frame (MapResetOptions): start-up begins
  // again with this frame as its reference.
  bool map_reset = false;
  double pyramid_ms = 0.0;
  double total_ms = 0.0;
};

// The poses of one map, from its initialisation to its reset (or the end):
// a monocular map has its own scale and origin, so segments are not joined.
struct TrajectorySegment {
  Trajectory final;   // recomposed from the map as it was at its reset (System::final_trajectory)
  Trajectory online;  // as tracked
};

class System {
 public:
  System(Camera camera, SlamOptions options);
  ~System();

  // Starts from a saved map instead of initialising (map_io); the first
  // frames relocalise against it.
  void load_map(const std::filesystem::path& path);

  // Builds the frame's pyramid, then starts up or tracks it.
  FrameReport process(Frame frame);
  // Waits for the map maker to finish queued work (threaded mode), then runs
  // a final global bundle adjustment in synchronous mode.
  void finish();

  // Every frame with a pose, camera-to-world, in processing order. Online:
  // the poses as tracked. Final: each frame's pose relative to its reference
  // keyframe recomposed with that keyframe's pose in the map now, which after
  // finish() is the map after its last bundle adjustment (relative_trajectory.hpp).
  Trajectory online_trajectory() const { return trajectory_.online(); }
  Trajectory final_trajectory() const;

  bool initialised() const { return initialised_; }
  // Maps given up so far, and the poses each of them tracked, in order (the
  // current map's are final_trajectory() and online_trajectory()).
  std::size_t map_resets() const { return map_resets_; }
  const std::vector<TrajectorySegment>& earlier_segments() const { return earlier_segments_; }
  const Map& map() const { return map_; }
  const Camera& camera() const { return camera_; }
  MapMakerStats map_maker_stats() const { return map_maker_.stats(); }
  // The semantic worker's figures; nothing when semantics are off.
  std::optional<semantics::SemanticWorkerStats> semantic_stats() const;

 private:
  void start_tracking(const SE3d& T_c_w, std::size_t frame_index, const Eigen::Matrix<double, 6, 1>& velocity);
  // Whether the map, lost since some frames, should be given up.
  bool should_reset(std::size_t frame_index) const;
  // Stops the threads, empties the map and everything made from it, and
  // makes `frame` start-up's new reference.
  void reset_map(const Frame& frame);
  // Records a frame with a pose against its reference keyframe, the
  // keyframe nearest the camera (relative_trajectory.hpp).
  void record_pose(const FrameReport& report);
  // One debug line per tracked frame: search outcomes, quality, stage times.
  void log_tracking(const FrameReport& report) const;

  Camera camera_;
  SlamOptions options_;
  Map map_;
  KeyFrameQueue queue_;
  KeyFramePointsQueue new_points_;  // map maker -> semantic worker
  std::unique_ptr<semantics::SemanticWorker> worker_;
  MapMaker map_maker_;
  Tracker tracker_;
  Initialiser initialiser_;
  bool initialised_ = false;
  std::size_t initialised_at_ = 0;  // the frame the map was initialised on
  bool map_loaded_ = false;         // a loaded map is relocalised against, never reset
  std::size_t map_resets_ = 0;
  std::vector<TrajectorySegment> earlier_segments_;
  // Keyframe candidates the tracker has asked for (the map maker's count of
  // those done at start_tracking, plus one per request): what
  // SlamOptions::max_keyframes_behind waits for.
  std::size_t keyframes_requested_ = 0;
  RelativeTrajectory trajectory_;
};

}  // namespace facadeslam
