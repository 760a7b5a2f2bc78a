#pragma once
// The tracked frames' trajectory, kept so that it can be written from the
// final map (what ORB-SLAM does): each frame's pose is stored relative to its
// reference keyframe, T_c_ref = T_c_w · T_ref_w⁻¹, and recomposed at the end
// with that keyframe's final pose, T_c_w = T_c_ref · T_ref_w. When the map
// maker corrects the map after a frame was tracked (a local or global bundle
// adjustment moving the keyframes and their points), the pose as tracked keeps
// the old map's error and the trajectory jumps where the correction landed;
// the recomposed pose moves with the keyframe the frame was measured against.
// The poses as tracked are kept too (trajectory_online.txt).
#include <cstddef>
#include <map>
#include <optional>
#include <vector>

#include "core/lie/se3.hpp"
#include "core/map/keyframe.hpp"
#include "core/map/map.hpp"
#include "core/trajectory/trajectory.hpp"

namespace facadeslam {

struct RelativeFramePose {
  std::size_t frame_index = 0;
  double timestamp = 0.0;
  std::optional<KeyFrame::Id> reference;  // none: the frame keeps its online pose
  SE3d T_c_ref;                           // the frame relative to its reference, as tracked
  SE3d T_c_w;                             // the pose as tracked (online)
};

class RelativeTrajectory {
 public:
  // Records a tracked frame: its pose and the pose its reference keyframe
  // had when the frame was tracked against it.
  void add(std::size_t frame_index, double timestamp, const SE3d& T_c_w, KeyFrame::Id reference, const SE3d& T_ref_w);
  // Records a tracked frame without a reference keyframe (none in the map).
  void add_online(std::size_t frame_index, double timestamp, const SE3d& T_c_w);

  const std::vector<RelativeFramePose>& frames() const { return frames_; }
  std::size_t size() const { return frames_.size(); }
  // Drops every frame (a map reset: their poses are in the old map's frame).
  void clear() { frames_.clear(); }

  // Camera-to-world poses as tracked, in the order they were added.
  Trajectory online() const;

  struct Recomposed {
    Trajectory trajectory;              // camera-to-world, one pose per frame added, same order as online()
    std::size_t fallbacks = 0;          // frames whose reference keyframe was not in `keyframes`
    std::size_t culled_references = 0;  // frames placed through culled keyframes' links
  };
  // Each frame recomposed with its reference keyframe's pose in `keyframes`
  // (the final map's). A reference the map maker culled is followed through
  // `culled` (Map::culled_keyframes) to a surviving keyframe. A frame whose
  // reference cannot be found that way keeps its online pose: its keyframe
  // went with its whole map (Map::clear), so every surviving keyframe
  // belongs to another map, with its own world frame and scale, and the
  // "nearest" of them would place the frame in the wrong frame.
  Recomposed recompose(const std::vector<KeyFrameSnapshot>& keyframes,
                       const std::map<KeyFrame::Id, CulledKeyFrame>& culled = {}) const;

 private:
  std::vector<RelativeFramePose> frames_;
};

}  // namespace facadeslam
