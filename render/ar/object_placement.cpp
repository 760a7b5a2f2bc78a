#include "render/ar/object_placement.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "core/util/angles.hpp"
#include "core/util/median.hpp"
#include "render/map_view_framing.hpp"

namespace facadeslam::render::ar {
namespace {

constexpr double kMaxGroundTiltDeg = 30.0;
constexpr std::size_t kMinCandidates = 8;
constexpr std::size_t kMinGroundPoints = 12;
constexpr double kBandShare = 0.15;    // inliers within this share of the camera height of the ground
constexpr double kLowestShare = 0.05;  // "the lowest points": this share of all
constexpr double kMaxSideTan = 0.36;   // the anchor within 20 degrees of the reference camera's axis

// A level plane (normal: the cameras' up) at the median height of
// `candidates` (indices into points), with the points within a band around
// it as inliers: the ground the cameras stand above. Nothing when it is not
// below the cameras or too few points lie on it.
std::optional<PlaneFit> level_ground(const std::vector<PlacementPoint>& points,
                                     const std::vector<std::size_t>& candidates, const Eigen::Vector3d& up_w,
                                     double camera_height) {
  if (candidates.size() < kMinCandidates) return std::nullopt;
  std::vector<double> heights;
  heights.reserve(candidates.size());
  for (const std::size_t i : candidates) heights.push_back(up_w.dot(points[i].p_w));
  std::nth_element(heights.begin(), heights.begin() + static_cast<std::ptrdiff_t>(heights.size() / 2), heights.end());
  const double ground = heights[heights.size() / 2];
  const double below = camera_height - ground;
  if (below <= 0.0) return std::nullopt;
  PlaneFit fit;
  fit.plane.normal_w = up_w;
  fit.plane.offset = -ground;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (std::abs(fit.plane.signed_distance(points[i].p_w)) <= kBandShare * below) fit.inliers.push_back(i);
  if (fit.inliers.size() < kMinGroundPoints) return std::nullopt;
  return fit;
}

// Where on the ground the object stands, as a fit for place_on_plane (its
// inliers index `points_w`, which may grow by one point). Among the ground's
// points within the middle of the reference camera's view, those from the
// median to the 80th percentile of depth: the object stands ahead, where the
// camera keeps it in view longer than at its feet (demo: in view in 119 of
// 119 frames, against 93 from the nearer half), not at the far end. A
// street's ground reaches far to the sides (pavements, lawns) and a road has
// few points: with fewer than ten in the middle of the view, a point of the
// plane straight ahead at their median depth (KITTI 06 snippet: otherwise
// placed 57 degrees off the axis, in view in 10 of 47 frames).
PlaneFit ground_anchor(const PlaneFit& fit, std::vector<Eigen::Vector3d>& points_w, const Eigen::Isometry3d& T_ref_w) {
  std::vector<std::pair<double, std::size_t>> by_depth;
  std::vector<double> depths;
  for (const std::size_t i : fit.inliers) {
    const Eigen::Vector3d p_ref = T_ref_w * points_w[i];
    if (p_ref.z() <= 0.0) continue;
    depths.push_back(p_ref.z());
    if (std::abs(p_ref.x()) <= kMaxSideTan * p_ref.z()) by_depth.emplace_back(p_ref.z(), i);
  }
  PlaneFit anchor = fit;
  anchor.inliers.clear();
  if (by_depth.size() >= 10) {
    std::sort(by_depth.begin(), by_depth.end());
    for (std::size_t k = by_depth.size() / 2; k < by_depth.size() * 4 / 5; ++k)
      anchor.inliers.push_back(by_depth[k].second);
    std::sort(anchor.inliers.begin(), anchor.inliers.end());
    return anchor;
  }
  if (depths.empty()) return fit;
  // Straight ahead: the optical axis laid on the plane, from the camera's foot.
  const Eigen::Isometry3d T_w_ref = T_ref_w.inverse();
  const Eigen::Vector3d n = fit.plane.normal_w;
  const Eigen::Vector3d camera_w = T_w_ref.translation();
  Eigen::Vector3d forward = T_w_ref.linear().col(2);
  forward -= forward.dot(n) * n;
  if (forward.norm() < 1e-6) return fit;  // looking straight down or up
  const Eigen::Vector3d foot = camera_w - fit.plane.signed_distance(camera_w) * n;
  points_w.emplace_back(foot + median(std::move(depths)) * forward.normalized());
  anchor.inliers.push_back(points_w.size() - 1);
  return anchor;
}

}  // namespace

std::optional<ObjectPlacement> place_object(const std::vector<PlacementPoint>& points,
                                            const std::vector<Eigen::Isometry3d>& keyframes_T_c_w,
                                            const PlacementOptions& options) {
  if (keyframes_T_c_w.empty()) return std::nullopt;
  const Eigen::Vector3d up_w = view_axes_from_cameras(keyframes_T_c_w).up_w;
  const Eigen::Isometry3d T_w_ref = keyframes_T_c_w.back().inverse();
  const Eigen::Vector3d camera_w = T_w_ref.translation();
  std::vector<Eigen::Vector3d> points_w;
  points_w.reserve(points.size());
  for (const PlacementPoint& p : points) points_w.push_back(p.p_w);

  std::optional<ObjectPlacement> placement;
  const auto try_plane = [&](const std::optional<PlaneFit>& fit, bool ground, const std::string& reason) {
    if (placement || !fit) return;
    std::vector<Eigen::Vector3d> anchor_points = points_w;
    const PlaneFit used = ground ? ground_anchor(*fit, anchor_points, T_w_ref.inverse()) : *fit;
    if (auto object = place_on_plane(used, anchor_points, T_w_ref, options))
      placement = ObjectPlacement{*object, *fit, ground, 0.0, reason};
  };

  std::vector<std::size_t> labelled;
  for (std::size_t i = 0; i < points.size(); ++i)
    if (points[i].labelled_ground) labelled.push_back(i);
  double camera_height = 0.0;
  for (const Eigen::Isometry3d& T_c_w : keyframes_T_c_w) camera_height += up_w.dot(T_c_w.inverse().translation());
  camera_height /= static_cast<double>(keyframes_T_c_w.size());
  try_plane(level_ground(points, labelled, up_w, camera_height), true, "points labelled road or pavement");

  // The lowest points of the map.
  std::vector<std::pair<double, std::size_t>> by_height;
  for (std::size_t i = 0; i < points.size(); ++i) by_height.emplace_back(up_w.dot(points[i].p_w), i);
  std::sort(by_height.begin(), by_height.end());
  std::vector<std::size_t> lowest;
  for (std::size_t k = 0; k < static_cast<std::size_t>(kLowestShare * static_cast<double>(by_height.size())); ++k)
    lowest.push_back(by_height[k].second);
  try_plane(level_ground(points, lowest, up_w, camera_height), true, "the lowest points, below the cameras");

  // The dominant plane may be level after all: then the object stands on it
  // as on any ground, straight ahead.
  const double cos_max_tilt = std::cos(deg_to_rad(kMaxGroundTiltDeg));
  const std::optional<PlaneFit> dominant = find_dominant_plane(points_w);
  const bool dominant_level = dominant && std::abs(dominant->plane.normal_w.dot(up_w)) >= cos_max_tilt;
  try_plane(dominant, dominant_level, "no ground plane in the map: its dominant plane");
  if (placement) {
    placement->on_ground = std::abs(placement->fit.plane.normal_w.dot(up_w)) >= cos_max_tilt;
    if (placement->on_ground)
      placement->ground_band = kBandShare * std::abs(placement->fit.plane.signed_distance(camera_w));
  }
  return placement;
}

}  // namespace facadeslam::render::ar
