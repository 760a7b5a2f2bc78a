#include "render/ar/plane_finder.hpp"
#include "core/util/median.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include <Eigen/Eigenvalues>

namespace facadeslam::render::ar {
// Named, so that the unity build's other render files cannot clash with these.
namespace plane_finder_detail {
namespace {

// Least-squares plane through the points: through their mean, normal along
// the smallest eigenvector of their scatter.
Plane fit_plane(const std::vector<Eigen::Vector3d>& points_w, const std::vector<std::size_t>& indices) {
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const std::size_t i : indices) mean += points_w[i];
  mean /= static_cast<double>(indices.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const std::size_t i : indices) {
    const Eigen::Vector3d d = points_w[i] - mean;
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> solver(scatter);
  Plane plane;
  plane.normal_w = solver.eigenvectors().col(0).normalized();  // eigenvalues ascending
  plane.offset = -plane.normal_w.dot(mean);
  return plane;
}

std::vector<std::size_t> inliers_of(const std::vector<Eigen::Vector3d>& points_w, const Plane& plane, double distance) {
  std::vector<std::size_t> inliers;
  for (std::size_t i = 0; i < points_w.size(); ++i)
    if (std::abs(plane.signed_distance(points_w[i])) <= distance) inliers.push_back(i);
  return inliers;
}

}  // namespace
}  // namespace plane_finder_detail

double plane_inlier_distance(const std::vector<Eigen::Vector3d>& points_w, const PlaneFinderOptions& options) {
  if (options.inlier_distance > 0.0 || points_w.empty()) return options.inlier_distance;
  // The median per axis is a robust centre; the median distance from it a
  // robust size of the map, whatever its (arbitrary) scale.
  Eigen::Vector3d centre;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> values;
    values.reserve(points_w.size());
    for (const Eigen::Vector3d& p : points_w) values.push_back(p[axis]);
    centre[axis] = median(std::move(values));
  }
  std::vector<double> distances;
  distances.reserve(points_w.size());
  for (const Eigen::Vector3d& p : points_w) distances.push_back((p - centre).norm());
  return options.relative_threshold * median(std::move(distances));
}

std::optional<PlaneFit> find_dominant_plane(const std::vector<Eigen::Vector3d>& points_w,
                                            const PlaneFinderOptions& options) {
  if (points_w.size() < std::max<std::size_t>(3, options.min_inliers)) return std::nullopt;
  const double distance = plane_inlier_distance(points_w, options);
  if (!(distance > 0.0)) return std::nullopt;
  // std::mt19937 is specified exactly; the index draw is done by hand because
  // uniform_int_distribution's algorithm differs between standard libraries.
  std::mt19937 random(options.seed);
  const auto draw = [&] { return static_cast<std::size_t>(random() % points_w.size()); };
  std::size_t best_count = 0;
  Plane best;
  for (int iteration = 0; iteration < options.iterations; ++iteration) {
    const Eigen::Vector3d& a = points_w[draw()];
    const Eigen::Vector3d& b = points_w[draw()];
    const Eigen::Vector3d& c = points_w[draw()];
    const Eigen::Vector3d normal = (b - a).cross(c - a);
    // Degenerate samples (repeated or collinear points) define no plane.
    if (normal.norm() <= 1e-12 * (b - a).squaredNorm() + 1e-300) continue;
    Plane candidate{normal.normalized(), 0.0};
    candidate.offset = -candidate.normal_w.dot(a);
    std::size_t count = 0;
    for (const Eigen::Vector3d& p : points_w) count += std::abs(candidate.signed_distance(p)) <= distance;
    if (count > best_count) {
      best_count = count;
      best = candidate;
    }
  }
  if (best_count < options.min_inliers) return std::nullopt;
  // Two rounds of least squares over the inliers, each with the inliers of
  // the plane before: the sample's three points fix the plane only roughly.
  PlaneFit fit{best, plane_finder_detail::inliers_of(points_w, best, distance)};
  for (int round = 0; round < 2; ++round) {
    const Plane refined = plane_finder_detail::fit_plane(points_w, fit.inliers);
    std::vector<std::size_t> inliers = plane_finder_detail::inliers_of(points_w, refined, distance);
    if (inliers.size() < options.min_inliers) break;
    fit = {refined, std::move(inliers)};
  }
  return fit;
}

double angle_between_deg(const Plane& a, const Plane& b) {
  const double cosine = std::min(1.0, std::abs(a.normal_w.normalized().dot(b.normal_w.normalized())));
  return std::acos(cosine) * 180.0 / std::numbers::pi;
}

}  // namespace facadeslam::render::ar
