#pragma once
// A calibrated camera: image size plus one of the projection models. Code
// that only needs double-precision projection uses the runtime-dispatched
// members; code that must see the concrete model (bundle adjustment builds
// one auto-diff functor per model) uses visit() or model().
//
// Conventions: pixel (0,0) is the centre of the top-left pixel, so the image
// covers [-0.5, width - 0.5] x [-0.5, height - 0.5]. unproject() returns a
// ray on the z = 1 plane; project() expects z > 0.
#include <string>
#include <utility>
#include <variant>

#include <Eigen/Core>
#include <opencv2/core.hpp>

#include "core/camera/atan_camera.hpp"
#include "core/camera/pinhole_radtan.hpp"

namespace facadeslam {

using CameraModel = std::variant<PinholeRadTan, AtanCamera>;

class Camera {
 public:
  // Throws Error unless width, height >= 1 and fx, fy are finite and > 0
  // (files are validated with better messages by load_camera).
  Camera(int width, int height, CameraModel model);

  int width() const { return width_; }
  int height() const { return height_; }
  const CameraModel& model() const { return model_; }
  // std::visit over the model: camera.visit([](const auto& m) { ... }).
  template <class Visitor>
  decltype(auto) visit(Visitor&& visitor) const {
    return std::visit(std::forward<Visitor>(visitor), model_);
  }
  // "pinhole" or "atan", the names used in the YAML files.
  std::string model_name() const;

  // Linear part shared by both models.
  double fx() const;
  double fy() const;
  double cx() const;
  double cy() const;
  // The same as a matrix: ideal pixel ~ K * ray (z = 1), distortion apart.
  Eigen::Matrix3d pinhole_matrix() const;

  Eigen::Vector2d project(const Eigen::Vector3d& p_c) const;
  Eigen::Vector3d unproject(const Eigen::Vector2d& px) const;
  Eigen::Matrix<double, 2, 3> project_jacobian(const Eigen::Vector3d& p_c) const;

  // True when px lies within the span of pixel centres shrunk by `border`:
  // border <= x <= width - 1 - border (same for y). With border 0 every such
  // point can be sampled by bilinear interpolation.
  bool in_image(const Eigen::Vector2d& px, double border = 0.0) const;

  // The camera of pyramid level `level` (>= 0) of a half-sampled pyramid in
  // which each level averages 2x2 blocks of the one below, so a level-0 pixel
  // coordinate x maps to x_l = (x + 0.5) / 2^l - 0.5: fx, fy scale by 2^-l,
  // cx_l = (cx + 0.5) / 2^l - 0.5, and each halving turns a size n into
  // n / 2 (an odd last row or column is dropped), exactly as
  // core/image/half_sample does. Distortion is in normalised coordinates and
  // does not change.
  Camera scaled_to_level(int level) const;

  // The same camera for the image resized to new_width x new_height (both
  // >= 1), under the same pixel-centre convention: x' = (x + 0.5) s - 0.5.
  Camera resized(int new_width, int new_height) const;

  // OpenCV interop: the 3x3 CV_64F camera matrix (valid for both models,
  // OpenCV uses the same pixel-centre convention) and the 1x5 CV_64F
  // coefficients (k1 k2 p1 p2 k3) of a pinhole camera. distortion() throws
  // Error for an ATAN camera: OpenCV has no FOV model, and returning zeros
  // would silently mis-project.
  cv::Mat K() const;
  cv::Mat distortion() const;

 private:
  int width_;
  int height_;
  CameraModel model_;
};

}  // namespace facadeslam
