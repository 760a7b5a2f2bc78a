#pragma once
// Ceres manifolds for SE3 and Sim3 parameter blocks, and the helpers that map
// the groups to and from those blocks (templated, so an auto-diff cost functor
// can read its pose as SE3<T> with T = ceres::Jet).
//
// Parameter layouts (Eigen's quaternion coefficient order, so that
// Eigen::Map<const Eigen::Quaternion<T>>(params) reads the rotation):
//   SE3 : 7 doubles [qx, qy, qz, qw, tx, ty, tz]
//   Sim3: 8 doubles [qx, qy, qz, qw, tx, ty, tz, log_scale]
// Sim3 stores the LOG of the scale, so every value of the block is a valid
// similarity (scale = exp(log_scale) > 0) and the update of that coordinate
// is additive.
//
// Both manifolds update on the LEFT, as the tracker does (se3.hpp):
//   Plus(x, delta)  = exp(delta) * x
//   Minus(y, x)     = log(y * x^-1)
// with delta = [rho, omega] (SE3) or [rho, omega, sigma] (Sim3). Plus writes a
// unit quaternion; Minus returns |omega| <= pi, so it does not depend on the
// sign of either quaternion. PlusJacobian and MinusJacobian are analytic
// (row-major, as Ceres expects) and satisfy MinusJacobian * PlusJacobian = I.
// Plus and Minus return false only for an invalid input block (non-finite
// values, zero quaternion): Ceres aborts the solve when Plus(x, -gradient)
// fails, so a huge but finite delta must succeed (a Sim3 scale overflowing to
// inf is returned as such and rejected by the cost evaluation instead).
#include <ceres/manifold.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "core/lie/se3.hpp"
#include "core/lie/sim3.hpp"

namespace facadeslam {

inline constexpr int kSe3ParamSize = 7;
inline constexpr int kSim3ParamSize = 8;

// Reads an SE3 from a 7-value block [qx, qy, qz, qw, tx, ty, tz]. The
// quaternion is normalised; like everything used inside a cost functor this
// never throws (an invalid block gives NaN, which Ceres rejects as a step).
template <class T>
SE3<T> se3_from_params(const T* params) {
  return SE3<T>(SO3<T>::from_quaternion_unchecked(Eigen::Quaternion<T>(Eigen::Map<const Eigen::Quaternion<T>>(params))),
                Eigen::Matrix<T, 3, 1>(params[4], params[5], params[6]));
}

// Writes an SE3 into a 7-value block.
template <class T>
void se3_to_params(const SE3<T>& pose, T* params) {
  Eigen::Map<Eigen::Matrix<T, 4, 1>> quaternion(params);
  Eigen::Map<Eigen::Matrix<T, 3, 1>> translation(params + 4);
  quaternion = pose.unit_quaternion().coeffs();
  translation = pose.translation();
}

// Reads a Sim3 from an 8-value block [qx, qy, qz, qw, tx, ty, tz, log_scale]
// (never throws, like se3_from_params).
template <class T>
Sim3<T> sim3_from_params(const T* params) {
  using std::exp;
  return Sim3<T>::from_parts_unchecked(
      SO3<T>::from_quaternion_unchecked(Eigen::Quaternion<T>(Eigen::Map<const Eigen::Quaternion<T>>(params))),
      Eigen::Matrix<T, 3, 1>(params[4], params[5], params[6]), exp(params[7]));
}

// Writes a Sim3 into an 8-value block (the last value is log(scale)).
template <class T>
void sim3_to_params(const Sim3<T>& s, T* params) {
  using std::log;
  Eigen::Map<Eigen::Matrix<T, 4, 1>> quaternion(params);
  Eigen::Map<Eigen::Matrix<T, 3, 1>> translation(params + 4);
  quaternion = s.unit_quaternion().coeffs();
  translation = s.translation();
  params[7] = log(s.scale());
}

// SE3 parameter block (7 ambient, 6 tangent), left update.
class SE3Manifold final : public ceres::Manifold {
 public:
  int AmbientSize() const override { return kSe3ParamSize; }
  int TangentSize() const override { return SE3d::kDof; }
  // x_plus_delta = exp(delta) * x.
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  // d Plus(x, delta) / d delta at delta = 0 (7x6, row-major):
  //   rows q: [0, (w I - hat(v)) / 2; 0, -v^T / 2], rows t: [I, -hat(t)],
  // with q = (v, w) and t read from x.
  bool PlusJacobian(const double* x, double* jacobian) const override;
  // y_minus_x = log(y * x^-1).
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  // d Minus(y, x) / d y at y = x (6x7, row-major):
  //   rows rho: [2 hat(t) G, I], rows omega: [2 G, 0], G = [w I + hat(v), -v].
  bool MinusJacobian(const double* x, double* jacobian) const override;
};

// Sim3 parameter block (8 ambient, 7 tangent), left update.
class Sim3Manifold final : public ceres::Manifold {
 public:
  int AmbientSize() const override { return kSim3ParamSize; }
  int TangentSize() const override { return Sim3d::kDof; }
  // x_plus_delta = exp(delta) * x.
  bool Plus(const double* x, const double* delta, double* x_plus_delta) const override;
  // 8x7, row-major: rows q as SE3, rows t: [I, -hat(t), t], row log_scale: [0, 0, 1].
  bool PlusJacobian(const double* x, double* jacobian) const override;
  // y_minus_x = log(y * x^-1).
  bool Minus(const double* y, const double* x, double* y_minus_x) const override;
  // 7x8, row-major: rows rho: [2 hat(t) G, I, -t], rows omega: [2 G, 0, 0],
  // row sigma: [0, 0, 1].
  bool MinusJacobian(const double* x, double* jacobian) const override;
};

}  // namespace facadeslam
