#pragma once
// Start-up: everything from the first frame until the map maker has built
// the first map, in one state machine (PTAM's TrackForInitialMap, without
// the key press):
//
//   no reference --frame--> reference (its FAST corners are tracked by KLT)
//   reference --frame: too little parallax / degenerate--> reference (kept)
//   reference --frame: tracks died, or the map maker rejected the map--> restart
//   reference --frame: two views reconstructed and the map built--> done
//
// A restart makes the current frame the new reference; it is the only way
// back. Runs on the caller's thread, before the tracker starts.
#include <optional>

#include "core/camera/camera.hpp"
#include "core/image/frame.hpp"
#include "core/lie/se3.hpp"
#include "mapmaker/map_maker.hpp"
#include "slam/init/two_view_initialiser.hpp"

namespace facadeslam {

// The first map's second camera, where tracking starts.
struct StartPose {
  SE3d T_c_w;
  // The camera's motion per frame over the two views (the tangent of
  // T_second_first divided by the frames between them): the tracker's
  // motion model starts from it instead of from rest, which a car at 10 Hz
  // (a metre per frame) needs.
  Eigen::Matrix<double, 6, 1> velocity = Eigen::Matrix<double, 6, 1>::Zero();
  // The reference frame: the first keyframe, at the world origin. It was
  // fed before the map existed, so its pose is known only now.
  std::size_t reference_index = 0;
  double reference_timestamp = 0.0;
};

class Initialiser {
 public:
  Initialiser(const Camera& camera, const TwoViewOptions& options, MapMaker& map_maker);

  // Feeds one frame (with its pyramid). Returns the frame's pose once the
  // first map has been built from the reference and this frame.
  std::optional<StartPose> add_frame(const Frame& frame);
  // Start-up begins again with the next frame as the reference (a map reset).
  void reset() { reference_.reset(); }

 private:
  void restart(const Frame& frame, const char* why);

  TwoViewInitialiser two_view_;
  MapMaker& map_maker_;
  std::optional<Frame> reference_;
};

}  // namespace facadeslam
