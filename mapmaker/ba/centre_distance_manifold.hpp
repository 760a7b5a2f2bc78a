#pragma once
// A Ceres manifold for an SE3 pose block [qx qy qz qw tx ty tz] (T_c_w, the
// layout of SE3Manifold) whose camera centre c = -R^T t is held on a sphere
// of fixed radius around a fixed point: the scale anchor of a monocular
// bundle adjustment (ba_problem.hpp). 7 ambient values, 5 tangent ones:
//
//   delta = [a, b, omega]:  c' = anchor + radius * normalise(v + a e1 + b e2)
//                           R' = exp(omega) R           (left update, as SE3Manifold)
//                           t' = -R' c'
//
// with v = c - anchor and (e1, e2) an orthonormal basis of the plane
// orthogonal to v (so a, b are world-unit displacements along the sphere).
// The pose must already lie on the sphere: build the manifold with the radius
// measured from the pose itself (Plus(x, 0) = x then holds).
#include <memory>

#include <ceres/manifold.h>

#include <Eigen/Core>

namespace facadeslam {

// Throws Error unless the anchor is finite and radius is finite and > 0.
std::unique_ptr<ceres::Manifold> make_centre_distance_manifold(const Eigen::Vector3d& anchor, double radius);

}  // namespace facadeslam
