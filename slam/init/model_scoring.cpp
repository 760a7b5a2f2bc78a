#include "slam/init/model_scoring.hpp"

#include <cmath>
#include <limits>

#include <Eigen/Geometry>
#include <Eigen/LU>

namespace facadeslam {
namespace {

// Squared distance from `to` to the transfer of `from` through M, or +inf when
// the transfer lands at infinity.
double transfer_error2(const Eigen::Matrix3d& M, const Eigen::Vector2d& from, const Eigen::Vector2d& to) {
  const Eigen::Vector3d h = M * from.homogeneous();
  if (std::abs(h.z()) < 1e-12) return std::numeric_limits<double>::infinity();
  return (h.hnormalized() - to).squaredNorm();
}

// Squared distance from `point` to the line l (a x + b y + c = 0).
double line_distance2(const Eigen::Vector3d& l, const Eigen::Vector2d& point) {
  const double norm2 = l.x() * l.x() + l.y() * l.y();
  if (norm2 < 1e-300) return std::numeric_limits<double>::infinity();
  const double d = l.dot(point.homogeneous());
  return d * d / norm2;
}

}  // namespace

ModelScore score_homography(const Eigen::Matrix3d& H, const std::vector<Eigen::Vector2d>& ideal0,
                            const std::vector<Eigen::Vector2d>& ideal1, double sigma_px) {
  ModelScore result;
  result.inliers.assign(ideal0.size(), false);
  Eigen::FullPivLU<Eigen::Matrix3d> lu(H);
  if (!H.allFinite() || !lu.isInvertible()) return result;
  const Eigen::Matrix3d H_inv = lu.inverse();
  const double inv_sigma2 = 1.0 / (sigma_px * sigma_px);
  for (std::size_t i = 0; i < ideal0.size(); ++i) {
    bool inlier = true;
    for (const double chi2 : {transfer_error2(H, ideal0[i], ideal1[i]) * inv_sigma2,
                              transfer_error2(H_inv, ideal1[i], ideal0[i]) * inv_sigma2}) {
      if (chi2 > kChiSquare95TwoDof)
        inlier = false;
      else
        result.score += kChiSquare95TwoDof - chi2;
    }
    result.inliers[i] = inlier;
    result.inlier_count += inlier ? 1 : 0;
  }
  return result;
}

ModelScore score_fundamental(const Eigen::Matrix3d& F, const std::vector<Eigen::Vector2d>& ideal0,
                             const std::vector<Eigen::Vector2d>& ideal1, double sigma_px) {
  ModelScore result;
  result.inliers.assign(ideal0.size(), false);
  if (!F.allFinite()) return result;
  const double inv_sigma2 = 1.0 / (sigma_px * sigma_px);
  for (std::size_t i = 0; i < ideal0.size(); ++i) {
    bool inlier = true;
    // Distance of x1 to the epipolar line of x0 in view 1, and vice versa.
    for (const double chi2 : {line_distance2(F * ideal0[i].homogeneous(), ideal1[i]) * inv_sigma2,
                              line_distance2(F.transpose() * ideal1[i].homogeneous(), ideal0[i]) * inv_sigma2}) {
      if (chi2 > kChiSquare95OneDof)
        inlier = false;
      else
        result.score += kChiSquare95TwoDof - chi2;
    }
    result.inliers[i] = inlier;
    result.inlier_count += inlier ? 1 : 0;
  }
  return result;
}

}  // namespace facadeslam
