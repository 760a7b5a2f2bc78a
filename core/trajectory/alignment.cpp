#include "core/trajectory/alignment.hpp"

#include <string>

#include <Eigen/LU>
#include <Eigen/SVD>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

Eigen::Vector3d mean_of(const std::vector<Eigen::Vector3d>& points) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& p : points) sum += p;
  return sum / static_cast<double>(points.size());
}

// Rotation about a line through collinear points is undetermined, so the
// spread of each set must span at least a plane. Relative threshold: the
// second principal direction must carry more than a 1e-10 share of the first.
bool spans_a_plane(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& mean) {
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const auto& p : points) scatter += (p - mean) * (p - mean).transpose();
  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(scatter);
  const Eigen::Vector3d sv = svd.singularValues();  // descending
  return sv(0) > 0.0 && sv(1) > 1e-10 * sv(0);
}

}  // namespace

Sim3Alignment umeyama_alignment(const std::vector<Eigen::Vector3d>& source, const std::vector<Eigen::Vector3d>& target,
                                bool with_scale) {
  if (source.size() != target.size())
    throw Error("trajectory alignment: the point sets differ in size (" + std::to_string(source.size()) + " vs " +
                std::to_string(target.size()) + ")");
  if (source.size() < 3)
    throw Error("trajectory alignment needs at least 3 associated pose pairs, got " + std::to_string(source.size()));

  const Eigen::Vector3d mu_source = mean_of(source);
  const Eigen::Vector3d mu_target = mean_of(target);
  if (!spans_a_plane(source, mu_source) || !spans_a_plane(target, mu_target))
    throw Error("trajectory alignment is undetermined: the " + std::to_string(source.size()) +
                " associated positions lie on one line (or one point); expected a trajectory that spans "
                "at least a plane");

  const double n = static_cast<double>(source.size());
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();  // (1/n) sum (y - mu_y)(x - mu_x)^T
  double source_variance = 0.0;                          // (1/n) sum |x - mu_x|^2
  for (std::size_t i = 0; i < source.size(); ++i) {
    const Eigen::Vector3d x = source[i] - mu_source;
    const Eigen::Vector3d y = target[i] - mu_target;
    covariance += y * x.transpose();
    source_variance += x.squaredNorm();
  }
  covariance /= n;
  source_variance /= n;

  const Eigen::JacobiSVD<Eigen::Matrix3d> svd(covariance, Eigen::ComputeFullU | Eigen::ComputeFullV);
  const Eigen::Matrix3d& U = svd.matrixU();
  const Eigen::Matrix3d& V = svd.matrixV();
  // Flip the weakest axis when U V^T would be a reflection (Umeyama eq. 39/43).
  Eigen::Vector3d S = Eigen::Vector3d::Ones();
  if (U.determinant() * V.determinant() < 0.0) S(2) = -1.0;

  Sim3Alignment result;
  result.R = U * S.asDiagonal() * V.transpose();
  result.scale = with_scale ? svd.singularValues().dot(S) / source_variance : 1.0;
  result.t = mu_target - result.scale * result.R * mu_source;
  return result;
}

}  // namespace facadeslam
