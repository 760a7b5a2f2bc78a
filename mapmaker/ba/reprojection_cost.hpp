#pragma once
// The bundle adjustment residual, templated on the camera model so that Ceres
// auto-differentiates through the concrete projection (PinholeRadTan or
// AtanCamera; Camera::visit picks the instantiation):
//
//   r = (project(T_c_w * p_w) - pixel) / 2^level        (2 values, "whitened":
//                                                        unit sigma per level)
//
// with the pose read from a 7-value SE3Manifold block [qx qy qz qw tx ty tz]
// and the point from a 3-value block. whitened_reprojection_residual() is the
// same function on an SE3 (used for the RMS and the outlier test).
//
// Points behind or beside the camera: project() divides by the depth, so a
// point at z <= 0 would give inf/NaN or a mirrored pixel. Such a point is
// instead projected as if its depth were raised to the limiting cone
// z = |p_c|_1 / kMaxNormalisedRadius (~89.9 degrees off the optical axis;
// plus a tiny absolute floor for a point at the camera centre), and that
// residual is held CONSTANT: its derivatives are zero. So
//  * everything stays finite (normalised coordinates are at most 1000),
//  * the cost is continuous (at the cone the clamped and the true projection
//    coincide), and large (~1000 focal lengths for the pinhole model, ~800 px
//    for the ATAN model at w = 0.9), so the observation counts as the outlier
//    it is and is reported by the chi-square test (BundleAdjuster also
//    reports every observation with z <= 0 after the solve);
//  * it cannot drag its camera or its point around: a clamped residual with
//    live derivatives has a gradient of the same order as an inlier's even
//    under a robust loss (huge residual x huge Jacobian), which in tests moved
//    a whole street of cameras by decimetres. A point whose observations are
//    all behind stays where it is, to be removed by the map maker.
// The cone is scale-free, which matters because a monocular map has an
// arbitrary scale.
#include <cmath>

#include <ceres/jet.h>

#include <Eigen/Core>

#include "core/lie/manifolds.hpp"
#include "core/lie/se3.hpp"
#include "mapmaker/ba/pose_block.hpp"

namespace facadeslam {

inline constexpr double kMaxNormalisedRadius = 1e3;
// Absolute floor (world units) so that a point exactly at the camera centre
// does not divide 0 by 0.
inline constexpr double kMinClampedDepth = 1e-9;

// The smallest depth a point p_c may have to be projected normally.
inline double min_field_depth(const Eigen::Vector3d& p_c) {
  return p_c.cwiseAbs().sum() * (1.0 / kMaxNormalisedRadius) + kMinClampedDepth;
}

// p_c with its depth raised to the limiting cone when the point is behind or
// too far beside the camera (see above).
inline Eigen::Vector3d clamp_to_field(const Eigen::Vector3d& p_c) {
  const double min_depth = min_field_depth(p_c);
  return p_c.z() >= min_depth ? p_c : Eigen::Vector3d(p_c.x(), p_c.y(), min_depth);
}

namespace ba_detail {
inline double value_of(double x) { return x; }
template <class S, int N>
S value_of(const ceres::Jet<S, N>& x) {
  return x.a;
}
}  // namespace ba_detail

// The constant residual of a point outside the field (kept out of line: the
// rare path should not weigh on the inlined auto-diff code).
template <class Model>
[[gnu::noinline]] Eigen::Vector2d residual_outside_field(const Model& model, const Eigen::Vector3d& p_c,
                                                         const Eigen::Vector2d& pixel, double inv_sigma) {
  return (model.project(clamp_to_field(p_c)) - pixel) * inv_sigma;
}

// The whitened residual of a camera-frame point, for T = double or ceres::Jet.
template <class Model, class T>
Eigen::Matrix<T, 2, 1> residual_in_camera(const Model& model, const Eigen::Matrix<T, 3, 1>& p_c,
                                          const Eigen::Vector2d& pixel, double inv_sigma) {
  const Eigen::Vector3d value(ba_detail::value_of(p_c.x()), ba_detail::value_of(p_c.y()), ba_detail::value_of(p_c.z()));
  if (value.z() >= min_field_depth(value)) [[likely]] {
    const Eigen::Matrix<T, 2, 1> px = model.project(p_c);
    return {(px.x() - pixel.x()) * inv_sigma, (px.y() - pixel.y()) * inv_sigma};
  }
  // Outside the field: the value at the cone, held constant (T(double) has
  // zero derivatives).
  const Eigen::Vector2d constant = residual_outside_field(model, value, pixel, inv_sigma);
  return {T(constant.x()), T(constant.y())};
}

// The whitened residual for any scalar type (double or ceres::Jet).
template <class Model, class T>
Eigen::Matrix<T, 2, 1> whitened_reprojection_residual(const Model& model, const SE3<T>& T_c_w,
                                                      const Eigen::Matrix<T, 3, 1>& p_w, const Eigen::Vector2d& pixel,
                                                      double inv_sigma) {
  return residual_in_camera<Model, T>(model, T_c_w * p_w, pixel, inv_sigma);
}

// Ceres functor: parameter blocks (pose 7, point 3), residual 2.
template <class Model>
class ReprojectionCost {
 public:
  // `model` must outlive the functor (it is the Camera passed to solve()).
  ReprojectionCost(const Model& model, const Eigen::Vector2d& pixel, int level)
      : model_(&model), pixel_(pixel), inv_sigma_(std::ldexp(1.0, -level)) {}

  // The pose block is read in place (pose_block.hpp: 1.8x faster than
  // building an SE3 from it).
  template <class T>
  bool operator()(const T* pose, const T* point, T* residual) const {
    const Eigen::Matrix<T, 3, 1> p_c = to_camera_frame(pose, point);
    Eigen::Map<Eigen::Matrix<T, 2, 1>> r(residual);
    r = residual_in_camera<Model, T>(*model_, p_c, pixel_, inv_sigma_);
    return true;
  }

 private:
  const Model* model_;
  Eigen::Vector2d pixel_;
  double inv_sigma_;
};

}  // namespace facadeslam
