#include "mapmaker/init/essential_refinement.hpp"

#include <cmath>

#include <Eigen/Cholesky>

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

double huber_cost(double r, double k) {
  const double a = std::abs(r);
  return a <= k ? r * r : 2.0 * k * a - k * k;
}

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

  const auto residuals = [&](const Pose& pose) {
    const Eigen::Matrix3d E = essential(pose);
    Eigen::VectorXd r(static_cast<Eigen::Index>(indices.size()));
    for (std::size_t n = 0; n < indices.size(); ++n) {
      const auto i = static_cast<std::size_t>(indices[n]);
      r(static_cast<Eigen::Index>(n)) = sampson_distance(E, rays0[i], rays1[i]);
    }
    return r;
  };
  const auto cost = [&](const Eigen::VectorXd& r) {
    double c = 0.0;
    for (Eigen::Index n = 0; n < r.size(); ++n) c += huber_cost(r(n), k);
    return c;
  };

  Pose pose{T_c1_c0.so3(), T_c1_c0.translation() / length};
  Eigen::VectorXd r = residuals(pose);
  double current = cost(r);
  double lambda = 1e-4;
  for (int iteration = 0; iteration < options.max_iterations; ++iteration) {
    // Central-difference Jacobian: 5 parameters, a few hundred residuals,
    // run once per start-up, so clarity wins over an analytic derivative.
    const Eigen::Matrix<double, 3, 2> B = tangent_basis(pose.direction);
    Eigen::MatrixXd J(r.size(), 5);
    constexpr double h = 1e-7;
    for (int p = 0; p < 5; ++p) {
      Vector5 step = Vector5::Zero();
      step(p) = h;
      J.col(p) = (residuals(perturbed(pose, B, step)) - residuals(perturbed(pose, B, -step))) / (2.0 * h);
    }
    // Iteratively reweighted least squares for the Huber loss.
    Eigen::VectorXd w(r.size());
    for (Eigen::Index n = 0; n < r.size(); ++n) w(n) = std::abs(r(n)) <= k ? 1.0 : k / std::abs(r(n));
    const Eigen::Matrix<double, 5, 5> H = J.transpose() * w.asDiagonal() * J;
    const Vector5 g = J.transpose() * w.asDiagonal() * r;

    bool improved = false;
    while (lambda < 1e8) {
      Eigen::Matrix<double, 5, 5> damped = H;
      damped.diagonal() += lambda * H.diagonal().cwiseMax(1e-12);
      const Vector5 delta = damped.ldlt().solve(-g);
      if (!delta.allFinite()) break;
      const Pose candidate = perturbed(pose, B, delta);
      const Eigen::VectorXd r_candidate = residuals(candidate);
      const double c = cost(r_candidate);
      if (c < current) {
        const bool converged = delta.norm() < 1e-12 || (current - c) < 1e-12 * current;
        pose = candidate;
        r = r_candidate;
        current = c;
        lambda = std::max(lambda * 0.1, 1e-10);
        improved = !converged;
        break;
      }
      lambda *= 10.0;
    }
    if (!improved) break;
  }
  return SE3d(pose.rotation, pose.direction * length);
}

}  // namespace facadeslam
