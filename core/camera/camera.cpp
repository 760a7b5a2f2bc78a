#include "core/camera/camera.hpp"

#include <cmath>
#include <type_traits>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

// Both models share fx fy cx cy with the same meaning, so rescaling the
// image only touches those: x' = (x + 0.5) s - 0.5 per axis.
CameraModel rescaled(const CameraModel& model, double sx, double sy) {
  return std::visit(
      [&](auto m) -> CameraModel {
        m.fx *= sx;
        m.fy *= sy;
        m.cx = (m.cx + 0.5) * sx - 0.5;
        m.cy = (m.cy + 0.5) * sy - 0.5;
        return m;
      },
      model);
}

}  // namespace

Camera::Camera(int width, int height, CameraModel model) : width_(width), height_(height), model_(std::move(model)) {
  if (width_ < 1 || height_ < 1)
    throw Error("camera: image size must be at least 1x1 pixels, got " + std::to_string(width_) + "x" +
                std::to_string(height_));
  if (!(std::isfinite(fx()) && fx() > 0.0 && std::isfinite(fy()) && fy() > 0.0))
    throw Error("camera: focal lengths fx, fy must be finite and > 0");
  if (!(std::isfinite(cx()) && std::isfinite(cy()))) throw Error("camera: principal point cx, cy must be finite");
  if (const auto* pinhole = std::get_if<PinholeRadTan>(&model_)) {
    for (double k : {pinhole->k1, pinhole->k2, pinhole->p1, pinhole->p2, pinhole->k3})
      if (!std::isfinite(k)) throw Error("camera: distortion coefficients must be finite");
  }
  if (const auto* atan_model = std::get_if<AtanCamera>(&model_)) {
    // tan(w/2) must be finite and non-negative for the model to be defined.
    if (!(atan_model->w >= 0.0 && atan_model->w < 3.0))
      throw Error("camera: ATAN parameter w must be in [0, 3) radians, got " + std::to_string(atan_model->w));
  }
}

std::string Camera::model_name() const {
  return visit([](const auto& m) -> std::string {
    using M = std::decay_t<decltype(m)>;
    if constexpr (std::is_same_v<M, PinholeRadTan>)
      return "pinhole";
    else
      return "atan";
  });
}

double Camera::fx() const {
  return visit([](const auto& m) { return m.fx; });
}
double Camera::fy() const {
  return visit([](const auto& m) { return m.fy; });
}
double Camera::cx() const {
  return visit([](const auto& m) { return m.cx; });
}
double Camera::cy() const {
  return visit([](const auto& m) { return m.cy; });
}

Eigen::Matrix3d Camera::pinhole_matrix() const {
  Eigen::Matrix3d K = Eigen::Matrix3d::Identity();
  K(0, 0) = fx();
  K(1, 1) = fy();
  K(0, 2) = cx();
  K(1, 2) = cy();
  return K;
}

Eigen::Vector2d Camera::project(const Eigen::Vector3d& p_c) const {
  return visit([&](const auto& m) -> Eigen::Vector2d { return m.project(p_c); });
}

Eigen::Vector3d Camera::unproject(const Eigen::Vector2d& px) const {
  return visit([&](const auto& m) { return m.unproject(px); });
}

Eigen::Matrix<double, 2, 3> Camera::project_jacobian(const Eigen::Vector3d& p_c) const {
  return visit([&](const auto& m) { return m.project_jacobian(p_c); });
}

bool Camera::in_image(const Eigen::Vector2d& px, double border) const {
  return px(0) >= border && px(1) >= border && px(0) <= width_ - 1 - border && px(1) <= height_ - 1 - border;
}

Camera Camera::scaled_to_level(int level) const {
  if (level < 0) throw Error("camera: pyramid level must be >= 0, got " + std::to_string(level));
  int w = width_, h = height_;
  for (int l = 0; l < level; ++l) {
    w /= 2;
    h /= 2;
  }
  const double scale = std::ldexp(1.0, -level);
  return Camera(w, h, rescaled(model_, scale, scale));
}

Camera Camera::resized(int new_width, int new_height) const {
  if (new_width < 1 || new_height < 1)
    throw Error("camera: cannot resize to " + std::to_string(new_width) + "x" + std::to_string(new_height));
  const double sx = static_cast<double>(new_width) / width_;
  const double sy = static_cast<double>(new_height) / height_;
  return Camera(new_width, new_height, rescaled(model_, sx, sy));
}

cv::Mat Camera::K() const {
  cv::Mat K = cv::Mat::eye(3, 3, CV_64F);
  K.at<double>(0, 0) = fx();
  K.at<double>(1, 1) = fy();
  K.at<double>(0, 2) = cx();
  K.at<double>(1, 2) = cy();
  return K;
}

cv::Mat Camera::distortion() const {
  const auto* pinhole = std::get_if<PinholeRadTan>(&model_);
  if (!pinhole)
    throw Error("camera: the '" + model_name() +
                "' model has no OpenCV distortion coefficients (OpenCV has no FOV model)");
  cv::Mat d(1, 5, CV_64F);
  d.at<double>(0) = pinhole->k1;
  d.at<double>(1) = pinhole->k2;
  d.at<double>(2) = pinhole->p1;
  d.at<double>(3) = pinhole->p2;
  d.at<double>(4) = pinhole->k3;
  return d;
}

}  // namespace facadeslam
