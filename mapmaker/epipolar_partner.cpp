#include "mapmaker/epipolar_partner.hpp"

#include <cmath>
#include <limits>
#include <numbers>

#include "core/util/angles.hpp"
#include "core/map/keyframe.hpp"

namespace facadeslam {

std::optional<std::size_t> choose_epipolar_partner(const SE3d& T_new_w, double new_mean_depth,
                                                   const std::vector<SE3d>& others,
                                                   const EpipolarPartnerOptions& options) {
  const Eigen::Vector3d centre = T_new_w.inverse().translation();
  const Eigen::Vector3d axis = optical_axis_w(T_new_w);
  const double min_baseline = options.min_baseline * new_mean_depth;
  const double min_cos = std::cos(deg_to_rad(options.max_axis_angle_deg));

  // Best by distance in each tier: 0 = baseline and shared view, 1 = baseline, 2 = any.
  std::optional<std::size_t> best[3];
  double best_distance[3] = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
                             std::numeric_limits<double>::infinity()};
  for (std::size_t i = 0; i < others.size(); ++i) {
    const double distance = (others[i].inverse().translation() - centre).norm();
    const bool baseline = distance >= min_baseline;
    const bool shares_view = optical_axis_w(others[i]).dot(axis) >= min_cos;
    const int tier = baseline && shares_view ? 0 : baseline ? 1 : 2;
    for (int t = tier; t < 3; ++t)
      if (distance < best_distance[t]) {
        best_distance[t] = distance;
        best[t] = i;
      }
  }
  for (const auto& choice : best)
    if (choice) return choice;
  return std::nullopt;
}

std::optional<std::size_t> choose_far_epipolar_partner(const SE3d& T_new_w, double new_mean_depth,
                                                       const std::vector<SE3d>& others, std::optional<std::size_t> near,
                                                       const EpipolarPartnerOptions& options) {
  if (options.far_baseline <= 0.0) return std::nullopt;
  const Eigen::Vector3d centre = T_new_w.inverse().translation();
  const Eigen::Vector3d axis = optical_axis_w(T_new_w);
  const double min_baseline = options.far_baseline * new_mean_depth;
  const double min_cos = std::cos(deg_to_rad(options.max_axis_angle_deg));
  std::optional<std::size_t> best;
  double best_distance = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < others.size(); ++i) {
    if (near && *near == i) continue;
    const double distance = (others[i].inverse().translation() - centre).norm();
    if (distance < min_baseline || distance >= best_distance) continue;
    if (optical_axis_w(others[i]).dot(axis) < min_cos) continue;
    best = i;
    best_distance = distance;
  }
  return best;
}

bool moving_forward(const SE3d& T_new_w, const SE3d& T_near_w, const EpipolarPartnerOptions& options) {
  const Eigen::Vector3d motion = T_new_w.inverse().translation() - T_near_w.inverse().translation();
  if (motion.norm() < 1e-12) return false;
  return motion.normalized().dot(optical_axis_w(T_new_w)) >= std::cos(deg_to_rad(options.far_max_motion_angle_deg));
}

}  // namespace facadeslam
