#pragma once
// Cameras and numeric helpers shared by the camera tests.
#include <functional>
#include <random>
#include <string>

#include <Eigen/Core>
#include <ceres/jet.h>
#include <gtest/gtest.h>

#include "core/camera/atan_camera.hpp"
#include "core/camera/pinhole_radtan.hpp"
#include "core/util/error.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::test {

// OpenCV's sample camera (samples/data/left_intrinsics.yml), 640x480: its
// distortion is strong at the corners, the hard case for undistortion.
inline PinholeRadTan opencv_left_model() {
  return {.fx = 535.91573396163199,
          .fy = 535.91573396163199,
          .cx = 342.28315473308373,
          .cy = 235.57082909788173,
          .k1 = -0.26637260909660682,
          .k2 = -0.038588898922304653,
          .p1 = 0.0017831947042852964,
          .p2 = -0.00028122100441115472,
          .k3 = 0.23839153080878486};
}

inline AtanCamera ptam_example_model(double w = 0.93) {
  return {.fx = 450.0, .fy = 450.0, .cx = 319.5, .cy = 239.5, .w = w};
}

// Central differences of f at p (f: R^3 -> R^2).
inline Eigen::Matrix<double, 2, 3> numeric_jacobian(const std::function<Eigen::Vector2d(const Eigen::Vector3d&)>& f,
                                                    const Eigen::Vector3d& p, double h = 1e-6) {
  Eigen::Matrix<double, 2, 3> J;
  for (int i = 0; i < 3; ++i) {
    Eigen::Vector3d plus = p, minus = p;
    plus(i) += h;
    minus(i) -= h;
    J.col(i) = (f(plus) - f(minus)) / (2.0 * h);
  }
  return J;
}

// Value and derivative of model.project through ceres::Jet<double, 3>.
template <class Model>
Eigen::Matrix<double, 2, 3> autodiff_jacobian(const Model& model, const Eigen::Vector3d& p,
                                              Eigen::Vector2d* value = nullptr) {
  using Jet = ceres::Jet<double, 3>;
  Eigen::Matrix<Jet, 3, 1> p_jet;
  for (int i = 0; i < 3; ++i) p_jet(i) = Jet(p(i), i);
  const Eigen::Matrix<Jet, 2, 1> px = model.project(p_jet);
  Eigen::Matrix<double, 2, 3> J;
  for (int r = 0; r < 2; ++r) J.row(r) = px(r).v.transpose();
  if (value) *value = Eigen::Vector2d(px(0).a, px(1).a);
  return J;
}

// A camera-frame point in front of the camera whose ray falls within the
// image's field of view (normalised coordinates within +-x_range, +-y_range).
inline Eigen::Vector3d random_point_in_view(std::mt19937& rng, double x_range, double y_range) {
  std::uniform_real_distribution<double> nx(-x_range, x_range), ny(-y_range, y_range), depth(0.3, 30.0);
  const double z = depth(rng);
  return {nx(rng) * z, ny(rng) * z, z};
}

}  // namespace facadeslam::test
