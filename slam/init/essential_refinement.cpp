#include "slam/init/essential_refinement.hpp"

#include <cmath>

#include <optional>

#include "slam/init/robust_lm.hpp"

namespace facadeslam {
namespace {

using Vector5 = Eigen::Matrix<double, 5, 1>;

// A unit translation direction and two unit vectors orthogonal to it: the
// direction moves on the sphere as normalise(t + B beta).
Eigen::Matrix<double, 3, 2> tangent_basis(const Eigen::Vector3d& t) {
  Eigen::Vector3d helper = std::abs(t.x()) < 0.9 ? Eigen::Vector3d::UnitX() : Eigen::Vector3d::UnitY();
  Eigen::Matrix<double, 3, 2> B;
  B.col(0) = t.cross(helper).normalized();
  B.col(1) = t.cross(B.col(0)).normalized();
  return B;
}

struct Pose {
  SO3<double> rotation;
  Eigen::Vector3d direction;  // unit
};

Pose perturbed(const Pose& pose, const Eigen::Matrix<double, 3, 2>& B, const Vector5& delta) {
  return {SO3<double>::exp(delta.head<3>()) * pose.rotation, (pose.direction + B * delta.tail<2>()).normalized()};
}

Eigen::Matrix3d essential(const Pose& pose) { return SO3<double>::hat(pose.direction) * pose.rotation.matrix(); }

}  // namespace

double sampson_distance(const Eigen::Matrix3d& E, const Eigen::Vector3d& ray0, const Eigen::Vector3d& ray1) {
  const Eigen::Vector3d x0 = ray0 / ray0.z(), x1 = ray1 / ray1.z();
  const Eigen::Vector3d Ex0 = E * x0, Etx1 = E.transpose() * x1;
  const double denom2 = Ex0.x() * Ex0.x() + Ex0.y() * Ex0.y() + Etx1.x() * Etx1.x() + Etx1.y() * Etx1.y();
  if (denom2 <= 0.0) return 0.0;
  return x1.dot(Ex0) / std::sqrt(denom2);
}

Eigen::Matrix3d essential_from_pose(const SE3d& T_c1_c0) {
  return SO3<double>::hat(T_c1_c0.translation()) * T_c1_c0.rotation_matrix();
}

SE3d refine_relative_pose(const SE3d& T_c1_c0, const std::vector<Eigen::Vector3d>& rays0,
                          const std::vector<Eigen::Vector3d>& rays1, const std::vector<int>& indices,
                          const EssentialRefinementOptions& options) {
  const double length = T_c1_c0.translation().norm();
  if (!(length > 0.0) || indices.size() < 6) return T_c1_c0;
  const double k = options.huber_px / options.focal_px;  // Huber threshold in normalised units

  const auto residuals = [&](const Pose& pose) -> std::optional<Eigen::VectorXd> {
    const Eigen::Matrix3d E = essential(pose);
    Eigen::VectorXd r(static_cast<Eigen::Index>(indices.size()));
    for (std::size_t n = 0; n < indices.size(); ++n) {
      const auto i = static_cast<std::size_t>(indices[n]);
      r(static_cast<Eigen::Index>(n)) = sampson_distance(E, rays0[i], rays1[i]);
    }
    return r;
  };
  const auto retract = [](const Pose& pose, const Vector5& delta) {
    return perturbed(pose, tangent_basis(pose.direction), delta);
  };
  const Pose pose = robust_lm::minimise<5>(Pose{T_c1_c0.so3(), T_c1_c0.translation() / length}, k,
                                           options.max_iterations, residuals, retract);
  return SE3d(pose.rotation, pose.direction * length);
}

}  // namespace facadeslam
