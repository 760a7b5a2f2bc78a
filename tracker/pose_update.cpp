#include "tracker/pose_update.hpp"

#include <cmath>
#include <string>

#include <Eigen/Cholesky>

#include "core/image/image_pyramid.hpp"
#include "core/util/error.hpp"
#include "core/util/assert.hpp"

namespace facadeslam {
namespace {

using Vector6d = Eigen::Matrix<double, 6, 1>;

// Residual and Jacobian of one measurement at pose (R, t), scaled to level
// pixels, written to r[0..1] and the two row-major Jacobian rows j[0..11].
// Returns false (writing nothing) when the point is not in front of the
// camera or the projection is not finite.
template <class Model>
bool linearise(const Model& model, const Eigen::Matrix3d& R, const Eigen::Vector3d& t, const PoseMeasurement& m,
               double min_depth, double* r, double* j) {
  const Eigen::Vector3d p_c = R * m.p_w + t;
  if (!(p_c.z() > min_depth)) return false;
  const double inv_scale = 1.0 / ImagePyramid::level_scale(m.level);
  const Eigen::Vector2d residual = (m.pixel - model.project(p_c)) * inv_scale;
  if (!residual.allFinite()) return false;
  const Eigen::Matrix<double, 2, 3> J_pi = model.project_jacobian(p_c) * inv_scale;
  r[0] = residual(0);
  r[1] = residual(1);
  // J_pi [I, -hat(p_c)]: row k is [J_pi_k, p_c x J_pi_k].
  for (int k = 0; k < 2; ++k, j += 6) {
    const Eigen::Vector3d row = J_pi.row(k).transpose();
    const Eigen::Vector3d rotation = p_c.cross(row);
    j[0] = row(0);
    j[1] = row(1);
    j[2] = row(2);
    j[3] = rotation(0);
    j[4] = rotation(1);
    j[5] = rotation(2);
  }
  return true;
}

using RowJacobians = Eigen::Matrix<double, Eigen::Dynamic, 6, Eigen::RowMajor>;

// Residuals and Jacobians of all measurements at one pose, stacked: rows 2i
// and 2i + 1 belong to measurement i.
struct Linearisation {
  RowJacobians J;
  Eigen::VectorXd r;
  std::vector<std::uint8_t> usable;  // in front of the camera, finite
  std::vector<double> squared;       // |r_i|^2 of the usable ones (reordered by the median)

  double squared_norm(std::size_t i) const { return r.segment<2>(2 * static_cast<Eigen::Index>(i)).squaredNorm(); }

  // Fills everything and returns the robust scale sigma^2.
  template <class Model>
  double compute(const Model& model, const SE3d& T, std::span<const PoseMeasurement> measurements,
                 const PoseUpdateOptions& options) {
    const std::size_t n = measurements.size();
    J.resize(2 * static_cast<Eigen::Index>(n), 6);
    r.resize(2 * static_cast<Eigen::Index>(n));
    usable.assign(n, 0);
    squared.clear();
    const Eigen::Matrix3d R = T.rotation_matrix();
    const Eigen::Vector3d& t = T.translation();
    for (std::size_t i = 0; i < n; ++i) {
      const Eigen::Index row = 2 * static_cast<Eigen::Index>(i);
      usable[i] = linearise(model, R, t, measurements[i], options.min_depth, r.data() + row, J.row(row).data());
      if (usable[i]) {
        squared.push_back(squared_norm(i));
      } else {
        r.segment<2>(row).setZero();
        J.middleRows<2>(row).setZero();
      }
    }
    return robust_sigma_squared(squared, options.min_sigma_squared, options.median_to_sigma_squared);
  }
};

// Weighted normal equations H = J^T W J, g = J^T W r with one Tukey weight
// per measurement (both of its rows), summed point by point on H's upper
// triangle (21 of 36 entries).
struct NormalEquations {
  Matrix6d H;
  Vector6d g;

  void compute(const Linearisation& lin, const std::vector<double>& weights) {
    double h[6][6] = {}, v[6] = {};
    const double* j = lin.J.data();
    const double* r = lin.r.data();
    for (std::size_t i = 0; i < weights.size(); ++i, j += 12, r += 2) {
      const double w = weights[i];
      if (w == 0.0) continue;
      const double* a = j;
      const double* b = j + 6;
      for (int p = 0; p < 6; ++p) {
        const double wa = w * a[p], wb = w * b[p];
        for (int q = p; q < 6; ++q) h[p][q] += wa * a[q] + wb * b[q];
        v[p] += wa * r[0] + wb * r[1];
      }
    }
    for (int p = 0; p < 6; ++p) {
      g(p) = v[p];
      for (int q = p; q < 6; ++q) H(p, q) = H(q, p) = h[p][q];
    }
  }
};

// Tukey weights of all measurements times their prior weights (0 where
// unusable); returns the count > 0.
int tukey_weights(const Linearisation& lin, double squared_cut, std::span<const PoseMeasurement> measurements,
                  std::vector<double>& weights) {
  int positive = 0;
  for (std::size_t i = 0; i < weights.size(); ++i) {
    weights[i] = lin.usable[i] ? measurements[i].weight * tukey_weight(lin.squared_norm(i), squared_cut) : 0.0;
    positive += weights[i] > 0.0;
  }
  return positive;
}

// Solves H x = b when H is safely positive definite (its smallest LDLT
// pivot above 1e-12 of the largest); false otherwise or if x is not finite.
template <class Rhs, class Out>
bool solve_positive_definite(const Matrix6d& H, const Rhs& b, Out& x) {
  const Eigen::LDLT<Matrix6d> ldlt(H);
  const auto d = ldlt.vectorD();
  if (ldlt.info() != Eigen::Success || !(d.minCoeff() > 1e-12 * d.maxCoeff())) return false;
  x = ldlt.solve(b);
  return x.allFinite();
}

}  // namespace

Eigen::Matrix<double, 2, 6> pose_measurement_jacobian(const SE3d& T_c_w, const Eigen::Vector3d& p_w,
                                                      const Camera& camera) {
  const Eigen::Vector3d p_c = T_c_w * p_w;
  return camera.project_jacobian(p_c) * SE3d::left_update_point_jacobian_at(p_c);
}

PoseUpdateResult update_pose(const SE3d& T_c_w, std::span<const PoseMeasurement> measurements, const Camera& camera,
                             const PoseUpdateOptions& options) {
  for (const PoseMeasurement& m : measurements) {
    FACADESLAM_ASSERT(m.weight >= 0.0 && m.weight <= 1.0, "a measurement's prior weight is in [0, 1]");
    FACADESLAM_ASSERT(m.level >= 0 && m.level < kPyramidLevels, "a measurement's level is a pyramid level");
  }
  PoseUpdateResult result;
  result.T_c_w = T_c_w;
  const std::size_t n = measurements.size();
  result.weights.assign(n, 0.0);
  result.inliers.assign(n, 0);
  const double c2 = options.tukey_c * options.tukey_c;
  Linearisation lin;
  NormalEquations normal;

  camera.visit([&](const auto& model) {
    for (int it = 0; it < options.max_iterations; ++it) {
      const double sigma2 = lin.compute(model, result.T_c_w, measurements, options);
      tukey_weights(lin, c2 * sigma2, measurements, result.weights);
      normal.compute(lin, result.weights);
      Vector6d delta;
      if (!solve_positive_definite(normal.H, normal.g, delta)) break;
      result.T_c_w = SE3d::exp(delta) * result.T_c_w;
      result.iterations = it + 1;
      result.ok = true;
      if (delta.norm() < options.convergence) {
        result.converged = true;
        break;
      }
    }

    // Weights, inliers, RMS and information at the returned pose.
    result.sigma_squared = lin.compute(model, result.T_c_w, measurements, options);
    result.num_inliers = tukey_weights(lin, c2 * result.sigma_squared, measurements, result.weights);
    double sum_sq_px = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (result.weights[i] == 0.0) continue;
      result.inliers[i] = 1;
      const double scale = ImagePyramid::level_scale(measurements[i].level);
      sum_sq_px += lin.squared_norm(i) * scale * scale;
    }
    if (result.num_inliers > 0) result.inlier_rms_px = std::sqrt(sum_sq_px / result.num_inliers);
    normal.compute(lin, result.weights);
    result.information = normal.H;
    Matrix6d covariance;
    if (solve_positive_definite(normal.H, Matrix6d::Identity(), covariance)) result.covariance = covariance;
  });
  return result;
}

}  // namespace facadeslam
