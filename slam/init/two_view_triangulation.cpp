#include "slam/init/two_view_triangulation.hpp"

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>
#include <Eigen/SVD>

namespace facadeslam {

std::optional<Eigen::Vector3d> triangulate_dlt(const SE3d& T_c1_c0, const Eigen::Vector3d& ray0,
                                               const Eigen::Vector3d& ray1) {
  const Eigen::Matrix<double, 3, 4> P0 = Eigen::Matrix<double, 3, 4>::Identity();
  const Eigen::Matrix<double, 3, 4> P1 = T_c1_c0.matrix3x4();
  const Eigen::Vector2d x0 = ray0.hnormalized(), x1 = ray1.hnormalized();
  Eigen::Matrix4d A;
  A.row(0) = x0.x() * P0.row(2) - P0.row(0);
  A.row(1) = x0.y() * P0.row(2) - P0.row(1);
  A.row(2) = x1.x() * P1.row(2) - P1.row(0);
  A.row(3) = x1.y() * P1.row(2) - P1.row(1);
  const Eigen::JacobiSVD<Eigen::Matrix4d> svd(A, Eigen::ComputeFullV);
  const Eigen::Vector4d X = svd.matrixV().col(3);
  if (!X.allFinite() || std::abs(X(3)) < 1e-12 * X.head<3>().norm()) return std::nullopt;
  return X.head<3>() / X(3);
}

double parallax_angle(const SE3d& T_c1_c0, const Eigen::Vector3d& p_c0) {
  const Eigen::Vector3d centre1_c0 = T_c1_c0.inverse().translation();
  const Eigen::Vector3d a = p_c0, b = p_c0 - centre1_c0;
  // atan2 of |a x b| and a.b is accurate for the tiny angles that matter here.
  return std::atan2(a.cross(b).norm(), a.dot(b));
}

double PoseEvaluation::median_parallax_rad() const {
  if (consistent_parallax_rad.empty()) return 0.0;
  std::vector<double> values = consistent_parallax_rad;
  auto mid = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), mid, values.end());
  return *mid;
}

PoseEvaluation evaluate_pose(const Camera& camera, const SE3d& T_c1_c0, const TwoViewMatches& matches,
                             const std::vector<int>& indices, const PointCheckOptions& options) {
  PoseEvaluation eval;
  const double max_err2 = options.max_reprojection_error_px * options.max_reprojection_error_px;
  for (int i : indices) {
    const auto k = static_cast<std::size_t>(i);
    const std::optional<Eigen::Vector3d> p0 = triangulate_dlt(T_c1_c0, matches.rays0[k], matches.rays1[k]);
    if (!p0) continue;
    const Eigen::Vector3d p1 = T_c1_c0 * *p0;
    if (!(p0->z() > 0.0 && p1.z() > 0.0)) continue;
    const double err0 = (camera.project(*p0) - matches.pixels0[k]).squaredNorm();
    const double err1 = (camera.project(p1) - matches.pixels1[k]).squaredNorm();
    if (!(err0 <= max_err2 && err1 <= max_err2)) continue;
    const double parallax = parallax_angle(T_c1_c0, *p0);
    eval.consistent.push_back(i);
    eval.consistent_parallax_rad.push_back(parallax);
    if (parallax < options.min_parallax_rad) continue;
    eval.good.push_back(i);
    eval.good_points_c0.push_back(*p0);
    eval.good_reprojection_error_sum += std::sqrt(std::max(err0, err1));
  }
  return eval;
}

}  // namespace facadeslam
