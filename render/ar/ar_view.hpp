#pragma once
// The augmented view, off-screen (OSMesa): a camera image with, drawn over
// it through the same camera, the virtual object (a lit, checkered cube
// anchored in the world) and the map points measured in the frame as round
// dots (those the object hides left out), plus a legend; CV_8UC3 BGR at the
// camera's resolution.
//
// Geometry is the camera model's exactly. Points: their pixel is
// Camera::project() on the CPU (distortion included) and the dot is centred
// on it. The object: rasterised through the camera's pinhole (
// render/projection.hpp) when the camera has no distortion; otherwise
// through the wider virtual pinhole of render/distortion_resampler.hpp, and
// resampled to the real camera per pixel (bilinear, on the GPU) while it is
// composited over the image: the post-pass the synthetic renderer uses.
//
// One ArView owns one OSMesa context; use it from one thread at a time.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/camera/camera.hpp"
#include "render/ar/virtual_object.hpp"
#include "render/map_view.hpp"
#include "render/projection.hpp"

namespace facadeslam::render::ar {

struct ArPoint {
  Eigen::Vector3d p_w;
  cv::Vec3b colour_bgr;
};

struct ArFrameContent {
  cv::Mat image;  // CV_8UC3 BGR or CV_8UC1, the camera's size
  // Camera -> world; nothing (a frame not tracked) draws the image alone.
  std::optional<Eigen::Isometry3d> T_w_c;
  std::vector<ArPoint> points;
  std::optional<VirtualObject> object;
  // The map's occluders (render/ar/map_occlusion.hpp) in object_intrinsics()'
  // geometry: the object is hidden where they are nearer. Empty: nothing hides it.
  cv::Mat occluder_depth;
  std::vector<LegendEntry> legend;  // empty: none
};

struct ArViewStyle {
  float point_size = 5.f;      // dot diameter, pixels
  float outline_pixels = 1.f;  // darker ring around each dot
  // The object's light, in its own frame (so the shading is fixed to the
  // object): from above, in front and to the side.
  Eigen::Vector3d light_o = Eigen::Vector3d(0.45, -0.6, 1.0).normalized();
  double ambient = 0.35;
  cv::Vec3b object_bgr{40, 150, 250};  // orange
  cv::Vec3b checker_bgr{245, 240, 235};
  double near = 0.01;  // nothing of the object nearer than this is drawn (map units)
};

// What a render drew (for the report and tests).
struct ArFrameStats {
  std::size_t points_drawn = 0;  // in front of the camera, inside the image, not behind the object
  bool object_drawn = false;     // the object was rasterised (it may still be off-screen)
};

class ArView {
 public:
  // Creates the OSMesa context; Error if OSMesa cannot give OpenGL 4.5 core
  // or the camera cannot be rendered (a field of view of 90 degrees or more).
  explicit ArView(const Camera& camera, const ArViewStyle& style = {});
  ~ArView();
  ArView(const ArView&) = delete;
  ArView& operator=(const ArView&) = delete;

  // Error when the image is not of the camera's size and type.
  cv::Mat render(const ArFrameContent& content, ArFrameStats* stats = nullptr);

  const Camera& camera() const;
  // The pinhole the object is drawn through: the camera's own without
  // distortion, else the wider virtual pinhole it is resampled from.
  const PinholeIntrinsics& object_intrinsics() const;
  std::string gl_renderer() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace facadeslam::render::ar
