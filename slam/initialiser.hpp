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

class Initialiser {
 public:
  Initialiser(const Camera& camera, const TwoViewOptions& options, MapMaker& map_maker);

  // Feeds one frame (with its pyramid). Returns the frame's pose once the
  // first map has been built from the reference and this frame.
  std::optional<SE3d> add_frame(const Frame& frame);

 private:
  void restart(const Frame& frame, const char* why);

  TwoViewInitialiser two_view_;
  MapMaker& map_maker_;
  std::optional<Frame> reference_;
};

}  // namespace facadeslam
