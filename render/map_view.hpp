#pragma once
// The map seen from a virtual camera, off-screen (OSMesa, like
// offscreen_renderer.hpp): a point cloud as round dots of a fixed size in
// pixels, keyframe cameras as small wireframe pyramids and a trajectory as a
// polyline, with a legend, into an 8-bit BGR image. For the labelled map
// picture (`facadeslam render-map`) and the map view beside the AR view.
//
// Geometry follows render/projection.hpp exactly: a point that
// PinholeIntrinsics::project() maps to pixel (u, v) is drawn centred on
// pixel (u, v) (an odd point size covers u - s/2 .. u + s/2), in its colour
// byte for byte (no lighting, no blending, no anti-aliasing); nearer things
// hide farther ones. Lines are 1-pixel-exact only where a test needs it:
// they are drawn with the driver's wide lines.
//
// One MapView owns one OSMesa context; use it from one thread at a time.
#include <memory>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "render/projection.hpp"

namespace facadeslam::render {

// A line in the legend: a dot (a class) or a short line (keyframes, trajectory).
struct LegendEntry {
  std::string text;
  cv::Vec3b colour_bgr;
  bool line = false;
};

struct MapViewContent {
  std::vector<Eigen::Vector3f> points_w;
  std::vector<cv::Vec3b> colours_bgr;              // one per point
  std::vector<Eigen::Isometry3d> keyframes_T_c_w;  // drawn as pyramids; may be empty
  std::vector<Eigen::Vector3d> trajectory_w;       // camera centres in time order; may be empty
  std::vector<LegendEntry> legend;                 // empty: no legend
};

// The virtual camera: pinhole intrinsics (their size is the image size) and
// its pose. Nothing nearer than `near` (metres along the optical axis) is drawn.
struct MapViewCamera {
  PinholeIntrinsics intrinsics;
  Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();
  double near = 0.01;
};

struct MapViewStyle {
  cv::Scalar background_bgr{238, 238, 238};  // light neutral grey: the black "various" class shows
  float point_size = 5.f;                    // dot diameter in pixels
  // The dots' outer ring is drawn darker, so that light classes (unlabelled
  // is light grey) stand out from a light background. 0: flat dots.
  float outline_pixels = 1.f;
  float frustum_line_width = 1.f;         // pixels
  float trajectory_line_width = 3.f;      // pixels
  cv::Vec3b keyframe_bgr{200, 110, 20};   // a strong blue, no class has it
  cv::Vec3b trajectory_bgr{0, 140, 255};  // orange, no class has it
  double frustum_depth = 0.1;             // pyramid height in world units
};

class MapView {
 public:
  // Creates the OSMesa context; Error if OSMesa cannot give OpenGL 4.5 core.
  MapView();
  ~MapView();
  MapView(const MapView&) = delete;
  MapView& operator=(const MapView&) = delete;

  // The picture, CV_8UC3 BGR, camera.intrinsics.width x height. Error when
  // points and colours differ in number, the size is not in [16, 8192] or
  // OpenGL fails.
  cv::Mat render(const MapViewContent& content, const MapViewCamera& camera, const MapViewStyle& style = {});

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace facadeslam::render
