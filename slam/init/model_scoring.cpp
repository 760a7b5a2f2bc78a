#include "slam/init/model_scoring.hpp"

#include <cmath>
#include <limits>
#include <utility>

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

// A model with no inlier, for models that cannot be scored.
ModelScore no_inliers(std::size_t n) {
  ModelScore result;
  result.inliers.assign(n, false);
  return result;
}

// Scores correspondence i by its two chi-square errors, one per direction
// (`chi2(i)` gives the pair): an inlier when both are within `cut`; each one
// within it adds kChiSquare95TwoDof - chi2, the same offset for both models
// so that their scores compare (ORB-SLAM's scoring).
template <class ChiSquarePair>
ModelScore score_both_ways(std::size_t n, double cut, ChiSquarePair chi2) {
  ModelScore result = no_inliers(n);
  for (std::size_t i = 0; i < n; ++i) {
    bool inlier = true;
    const auto [forward, backward] = chi2(i);
    for (const double e : {forward, backward}) {
      if (e > cut)
        inlier = false;
      else
        result.score += kChiSquare95TwoDof - e;
    }
    result.inliers[i] = inlier;
    result.inlier_count += inlier ? 1 : 0;
  }
  return result;
}

}  // namespace

ModelScore score_homography(const Eigen::Matrix3d& H, const std::vector<Eigen::Vector2d>& ideal0,
                            const std::vector<Eigen::Vector2d>& ideal1, double sigma_px) {
  Eigen::FullPivLU<Eigen::Matrix3d> lu(H);
  if (!H.allFinite() || !lu.isInvertible()) return no_inliers(ideal0.size());
  const Eigen::Matrix3d H_inv = lu.inverse();
  const double inv_sigma2 = 1.0 / (sigma_px * sigma_px);
  return score_both_ways(ideal0.size(), kChiSquare95TwoDof, [&](std::size_t i) {
    return std::pair{transfer_error2(H, ideal0[i], ideal1[i]) * inv_sigma2,
                     transfer_error2(H_inv, ideal1[i], ideal0[i]) * inv_sigma2};
  });
}

ModelScore score_fundamental(const Eigen::Matrix3d& F, const std::vector<Eigen::Vector2d>& ideal0,
                             const std::vector<Eigen::Vector2d>& ideal1, double sigma_px) {
  if (!F.allFinite()) return no_inliers(ideal0.size());
  const double inv_sigma2 = 1.0 / (sigma_px * sigma_px);
  // Distance of x1 to the epipolar line of x0 in view 1, and vice versa.
  return score_both_ways(ideal0.size(), kChiSquare95OneDof, [&](std::size_t i) {
    return std::pair{line_distance2(F * ideal0[i].homogeneous(), ideal1[i]) * inv_sigma2,
                     line_distance2(F.transpose() * ideal1[i].homogeneous(), ideal0[i]) * inv_sigma2};
  });
}

}  // namespace facadeslam
