#pragma once
// The dominant plane of a map (RANSAC over its points), for standing the
// virtual object of the augmented view on: in a street map the largest plane
// is the ground or a facade. Deterministic: the same points and options give
// the same plane.
#include <cstddef>
#include <optional>
#include <vector>

#include <Eigen/Core>

namespace facadeslam::render::ar {

struct Plane {
  Eigen::Vector3d normal_w = Eigen::Vector3d::UnitZ();  // unit
  double offset = 0.0;                                  // normal_w . p + offset = 0 on the plane
  double signed_distance(const Eigen::Vector3d& p_w) const { return normal_w.dot(p_w) + offset; }
};

struct PlaneFit {
  Plane plane;
  std::vector<std::size_t> inliers;  // indices into the points, ascending
};

struct PlaneFinderOptions {
  // A point is an inlier within this distance of the plane. 0: chosen from
  // the points, as relative_threshold times the median distance of the points
  // from their median (maps have no metric scale).
  double inlier_distance = 0.0;
  double relative_threshold = 0.01;
  int iterations = 400;
  std::size_t min_inliers = 20;
  unsigned seed = 19;
};

// The plane with the most inliers, refined by least squares over them (the
// normal is the direction of least spread of the inliers); nothing when fewer
// than min_inliers points support any plane.
std::optional<PlaneFit> find_dominant_plane(const std::vector<Eigen::Vector3d>& points_w,
                                            const PlaneFinderOptions& options = {});

// The inlier distance find_dominant_plane uses for these points and options.
double plane_inlier_distance(const std::vector<Eigen::Vector3d>& points_w, const PlaneFinderOptions& options);

// The angle between two planes' normals in degrees, 0..90 (a plane's
// normal has no preferred sign).
double angle_between_deg(const Plane& a, const Plane& b);

}  // namespace facadeslam::render::ar
