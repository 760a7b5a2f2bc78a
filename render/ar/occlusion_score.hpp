#pragma once
// How well the map occludes the virtual object, against ground-truth depth
// (synthetic sequences): per rendered frame, the object's pixels the render
// hides (the map's occluders nearer than the object) and those the true
// scene hides (its depth nearer than the object's), summed over the frames:
// occlusion IoU = |both| / |either|. A renderer that hides nothing scores 0
// wherever the truth hides part of the object. Flicker: the mean change,
// from one rendered frame to the next, of the share of the object's pixels
// hidden (render and truth alike; the render's should not exceed the truth's).
#include <cstddef>
#include <optional>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>

#include "core/camera/camera.hpp"
#include "render/ar/virtual_object.hpp"

namespace facadeslam::render::ar {

// The object's z in the camera frame per pixel of the camera (a ray cast
// through the camera model), +infinity off the object; CV_32FC1.
cv::Mat object_depth(const VirtualObject& object, const Camera& camera, const Eigen::Isometry3d& T_c_w);

// Whether some pixel of the object (its z, +infinity off it) is left
// uncovered by `occluder_z` (empty: nothing occludes).
bool leaves_object_visible(const cv::Mat& object_z, const cv::Mat& occluder_z);

class OcclusionScore {
 public:
  // CV_32FC1 of one size: the object's z, the occluders' z the render used,
  // the true depth in the map's units (0 or +infinity: none). A pixel is
  // hidden when the other depth is nearer than the object's by 1 %.
  void add_frame(const cv::Mat& object_z, const cv::Mat& occluder_z, const cv::Mat& truth_z);

  std::size_t frames() const { return frames_; }
  // Frames where some object pixel is left visible by the render.
  std::size_t frames_visible() const { return frames_visible_; }
  // Nothing while no frame had a pixel hidden by either.
  std::optional<double> iou() const;
  // Of the object's pixels over all frames, the shares the render and the
  // truth hide; of the render's hidden pixels, the share the truth hides
  // too (precision, nothing while the render hides none), and of the
  // truth's, the share the render hides (recall, nothing while the truth hides none).
  double hidden_share_render() const { return object_ > 0 ? render_hidden_ / object_ : 0.0; }
  double hidden_share_truth() const { return object_ > 0 ? truth_hidden_ / object_ : 0.0; }
  std::optional<double> precision() const { return share(both_, render_hidden_); }
  std::optional<double> recall() const { return share(both_, truth_hidden_); }
  // The next frame shows another object (placed again): its hidden share
  // is not compared with this one's for flicker.
  void break_sequence() { last_render_share_.reset(), last_truth_share_.reset(); }
  double flicker_render() const { return changes_ ? flicker_render_ / static_cast<double>(changes_) : 0.0; }
  double flicker_truth() const { return changes_ ? flicker_truth_ / static_cast<double>(changes_) : 0.0; }

 private:
  std::size_t frames_ = 0, frames_visible_ = 0, changes_ = 0;
  static std::optional<double> share(double part, double whole) {
    return whole > 0 ? std::optional<double>(part / whole) : std::nullopt;
  }

  double both_ = 0, either_ = 0, flicker_render_ = 0, flicker_truth_ = 0;
  double object_ = 0, render_hidden_ = 0, truth_hidden_ = 0;
  std::optional<double> last_render_share_, last_truth_share_;
};

}  // namespace facadeslam::render::ar
