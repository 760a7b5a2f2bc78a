#pragma once
// The map view's camera for a replay: it follows the tracked camera from
// above and behind, looking over it at the map ahead, like a chase camera.
// "Up" is the map's up as render/map_view_framing.hpp derives it from the
// keyframes (maps have no gravity).
#include <Eigen/Geometry>

#include "render/map_view.hpp"
#include "render/map_view_framing.hpp"

namespace facadeslam::render::ar {

struct FollowCameraOptions {
  // Distances in units of the scene depth (the keyframes' median depth of
  // points): back along the camera's horizontal heading, up, and how far
  // ahead of the camera the view looks.
  double behind = 0.9;
  double above = 0.6;
  double look_ahead = 0.8;
  double horizontal_fov_deg = 70.0;
};

// A width x height view of the map for a camera at T_w_c.
MapViewCamera follow_camera(const Eigen::Isometry3d& T_w_c, const ViewAxes& axes, double scene_depth, int width,
                            int height, const FollowCameraOptions& options = {});

}  // namespace facadeslam::render::ar
