#pragma once
// Renders the frames of a synthetic sequence one at a time: the street at the
// frame's time through the camera at its ground-truth pose, with motion blur,
// lighting and pixel noise applied to the colour image. Labels and depth are
// those of the instant of the frame's timestamp (the middle of the exposure),
// the same instant as the ground-truth pose.
#include <string>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "render/offscreen_renderer.hpp"
#include "sequences/synth/camera_path.hpp"
#include "sequences/synth/scene.hpp"
#include "sequences/synth/street_scene.hpp"

namespace facadeslam::synth {

struct SynthFrame {
  int index = 0;
  double timestamp = 0.0;  // seconds: index / fps
  Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();
  cv::Mat colour;    // CV_8UC3 BGR
  cv::Mat labels;    // CV_8UC1 class ids (label_classes.hpp)
  cv::Mat depth_mm;  // CV_16UC1 z-depth in millimetres, 0 = none
};

class FrameSynthesizer {
 public:
  // Creates the renderer and uploads the scene's textures. `spec` must
  // outlive this object.
  explicit FrameSynthesizer(const SceneSpec& spec);

  int frame_count() const { return spec_.frames; }
  double timestamp(int index) const { return index / spec_.fps; }
  const CameraPath& path() const { return path_; }
  std::string gl_renderer() const { return renderer_.gl_renderer(); }

  // Frame `index` in [0, frame_count()).
  SynthFrame render(int index);

 private:
  const SceneSpec& spec_;
  render::Renderer renderer_;
  StreetScene street_;
  CameraPath path_;
};

}  // namespace facadeslam::synth
