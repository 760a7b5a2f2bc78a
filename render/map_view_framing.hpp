#pragma once
// Choosing the map view's virtual camera so that the map fills the picture.
//
// Which way is up: our maps have no gravity, but the cameras that made them
// are held upright, so "up" is the mean of the keyframes' -y axes, and the
// way they look (the mean optical axis, made horizontal) is "forward". A
// principal-component fit of the points was the alternative; it is not
// used because a street map is mostly facades, whose plane's normal (the
// smallest component) is horizontal, not up.
//
// Robust framing: the box that is framed spans the 2nd-98th percentile of
// the points along right / forward / up (configurable), so a few points
// triangulated far away do not shrink the map to a dot; the camera centres
// passed as anchors are always inside. The camera stands back along its
// optical axis from the box centre, and its focal length and principal point
// are then fitted to the projected points so that they fill the picture up
// to a margin (a crop of a wider view: the principal point may be off-centre).
#include <vector>

#include <Eigen/Geometry>

#include "render/map_view.hpp"

namespace facadeslam::render {

enum class MapViewKind {
  oblique,  // from behind the cameras and above, looking forward and down
  top,      // straight down, turned so that the map's long horizontal axis runs
            // along the picture's long side, the cameras' forward upwards
};

struct ViewAxes {
  Eigen::Vector3d up_w = -Eigen::Vector3d::UnitY();      // unit
  Eigen::Vector3d forward_w = Eigen::Vector3d::UnitZ();  // unit, orthogonal to up
};

// From keyframe poses (T_c_w) as described above. Without poses: the world
// frame's own -y and z (a map's world frame is its first keyframe's camera).
ViewAxes view_axes_from_cameras(const std::vector<Eigen::Isometry3d>& keyframes_T_c_w);

struct FramingOptions {
  double low_percentile = 2.0;  // the framed box, per axis, in percent
  double high_percentile = 98.0;
  double elevation_deg = 35.0;  // oblique: the view's angle below the horizontal
  double margin = 0.05;         // fraction of each image side left free around the map
};

struct MapViewFraming {
  MapViewCamera camera;
  double box_diagonal = 1.0;  // size of the framed box, world units (for pyramid sizes)
};

// Frames `points_w` (robustly) and `anchors_w` (always) in a width x height picture.
MapViewFraming frame_map_view(const std::vector<Eigen::Vector3f>& points_w,
                              const std::vector<Eigen::Vector3d>& anchors_w, const ViewAxes& axes, MapViewKind kind,
                              int width, int height, const FramingOptions& options = {});

}  // namespace facadeslam::render
