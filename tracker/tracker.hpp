#pragma once
// PTAM's tracker: every frame, project the map into the image, find the
// points' patches coarse-to-fine, update the pose robustly, judge the
// tracking quality, ask the map maker for keyframes, and relocalise when lost.
//
// The tracker runs on the caller's thread (the replay loop). It reads the map
// (a const Map: it never changes it) through snapshots and talks to the map
// maker only through the KeyFrameQueue. Deterministic: the only randomness,
// which points to search when there are too many, is seeded per frame.
#include <cstdint>
#include <memory>
#include <optional>
#include <utility>
#include <random>
#include <vector>

#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"
#include "core/image/frame.hpp"
#include "core/map/keyframe_candidate.hpp"
#include "core/map/map.hpp"
#include "core/patch/search_image.hpp"
#include "tracker/tracker_options.hpp"

namespace facadeslam {

enum class TrackingQuality { good, dodgy, bad };
const char* to_string(TrackingQuality quality);

struct StageTimings {
  double coarse_ms = 0, fine_ms = 0, pose_ms = 0, relocalise_ms = 0;
  double snapshot_ms = 0;  // copying the map's points for this frame
};

// Why the fine stage's searches failed (diagnostics, --verbose).
struct SearchCounts {
  int in_view = 0;           // map points in front of the camera and inside the image
  int bad_warp = 0;          // ... whose patch warp fits no search level (too strong a scale change)
  int projected = 0;         // map points projecting into the image with a usable warp
  int template_invalid = 0;  // no template (outside the source image, textureless)
  int no_candidate = 0;      // no FAST corner within the radius
  int score_too_high = 0;    // best corner's ZMSSD above the bound
  int subpixel_failed = 0;   // sub-pixel refinement did not converge
  int outliers = 0;          // found, then rejected by the robust pose update
};

struct TrackingResult {
  bool tracked = false;  // pose is valid for this frame
  TrackingQuality quality = TrackingQuality::bad;
  SE3d T_c_w;
  bool relocalised = false;  // tracking resumed on this frame after a loss
  bool keyframe_requested = false;
  int coarse_searched = 0, coarse_found = 0;
  bool coarse_pose_used = false;      // the fine stage started from the coarse stage's pose
  bool coarse_pose_rejected = false;  // ... which failed where the motion model's prediction did better
  int fine_searched = 0, fine_found = 0;
  int points_dropped = 0;        // projecting into the image, but of weight 0 (moving class): not searched
  int points_down_weighted = 0;  // found, of an unreliable or moving class: a lower weight in the pose update
  int points_verified = 0;       // ... of which the pose put within LabelPolicy::verify_px: full weight after all
  double inlier_rms_px = 0;
  // How far the pose found lies from the motion model's prediction
  // (rotation, and camera centre in map units): what the search radii must cover.
  double prediction_error_deg = 0, prediction_error_m = 0;
  SearchCounts fine_counts;
  StageTimings timings;
};

class Tracker {
 public:
  Tracker(Camera camera, const Map& map, KeyFrameQueue& keyframes, TrackerOptions options);

  // Starts tracking from a known pose (after initialisation or map loading)
  // and motion per frame (the motion model's first prediction).
  void start(const SE3d& T_c_w, std::size_t frame_index,
             const Eigen::Matrix<double, 6, 1>& velocity = Eigen::Matrix<double, 6, 1>::Zero());
  // The pose is unknown (a loaded map): relocalise from the next frame.
  void mark_lost() { lost_frames_ = std::max(lost_frames_, options_.lost_frames_before_relocalising); }

  // `frame` must have its pyramid; a keyframe made from it shares its images.
  TrackingResult track(const Frame& frame);

  bool is_lost() const { return lost_frames_ > 0; }
  // Frames in a row without a pose.
  int lost_frames() const { return lost_frames_; }
  // The map was reset: nothing to track until start() again.
  void reset();

 private:
  struct Candidate;  // a projected map point (tracker.cpp)

  // Map points that project into the image with a usable warp, except those
  // of weight 0 (moving classes; counted in `dropped`, if given) where enough
  // others are in view.
  std::vector<Candidate> project_map(const std::vector<PointSnapshot>& points, const SE3d& T_c_w,
                                     int* dropped = nullptr, SearchCounts* counts = nullptr) const;
  // Gives the down-weighted measurements that `update`'s pose reprojects
  // within LabelPolicy::verify_px their full weight and updates
  // the pose again from there; returns how many. `few_reliable`: only when
  // fewer than min_reliable_points full-weight measurements are inliers.
  enum class VerifyWhen { always, few_reliable };
  int verify_unreliable(PoseUpdateResult& update, std::vector<PoseMeasurement>& measurements, VerifyWhen when) const;
  // The found points as pose-update measurements (snapshot geometry),
  // unreliable ones with their lower weight (counted in `down_weighted`).
  std::vector<PoseMeasurement> pose_measurements(const std::vector<PointSnapshot>& points,
                                                 const std::vector<PointMeasurement>& found, int* down_weighted) const;
  // Searches up to `max_points` of `candidates` (in order) in the frame's
  // search image and returns the measurements found; `searched` counts the
  // attempts, `counts` (optional) why the others failed.
  std::vector<PointMeasurement> search(const std::vector<PointSnapshot>& points,
                                       const std::vector<Candidate>& candidates, const patch::SearchImage& image,
                                       double radius_level0, int max_points, int& searched, SearchCounts* counts) const;
  // The coarse (unless `coarse` is false) + fine stages and pose updates
  // from `T_start`; fills `result`.
  std::vector<PointMeasurement> track_from(const SE3d& T_start, const Frame& frame, TrackingResult& result,
                                           bool coarse = true);
  // A frame tracked from one starting pose: its figures and the measurements
  // the pose kept (they go to a keyframe if one is made).
  struct TrackedFrame {
    TrackingResult result;
    std::vector<PointMeasurement> inliers;
  };
  // A pose for a lost frame: the small blurry image's, else ORB + PnP's;
  // either only if the normal search from it tracks well.
  std::optional<TrackedFrame> relocalise(const Frame& frame);
  enum class KeyFrameReason { none, moved, turned };
  KeyFrameReason wants_keyframe(const TrackingResult& result, std::size_t frame_index) const;
  void consider_keyframe(const Frame& frame, TrackingResult& result, std::vector<PointMeasurement> inliers);
  void request_keyframe(const Frame& frame, const SE3d& T_c_w, std::vector<PointMeasurement> measurements,
                        KeyFrameReason reason);

  Camera camera_;
  const Map& map_;
  KeyFrameQueue& keyframes_;
  TrackerOptions options_;
  DescriptorRelocaliser descriptor_relocaliser_;

  bool started_ = false;
  SE3d T_c_w_;
  Eigen::Matrix<double, 6, 1> velocity_ = Eigen::Matrix<double, 6, 1>::Zero();
  int lost_frames_ = 0;
  std::size_t last_keyframe_frame_ = 0;
  bool last_keyframe_turned_ = false;
  int found_at_keyframe_ = 0;  // most points found in a frame since the last keyframe request
  // The map's points as of Map revision points_revision_ (Map::refresh_points_snapshot).
  std::vector<PointSnapshot> points_;
  std::uint64_t points_revision_ = 0;
};

}  // namespace facadeslam
