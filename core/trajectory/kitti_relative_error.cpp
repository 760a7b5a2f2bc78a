#include "core/trajectory/kitti_relative_error.hpp"

#include <algorithm>
#include <cstdio>
#include <string>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

// Distance along the ground truth from its first pose to each pose.
std::vector<double> distances_along(const std::vector<Eigen::Isometry3d>& T_w_c) {
  std::vector<double> distances;
  distances.reserve(T_w_c.size());
  for (std::size_t i = 0; i < T_w_c.size(); ++i)
    distances.push_back(i == 0 ? 0.0 : distances.back() + (T_w_c[i].translation() - T_w_c[i - 1].translation()).norm());
  return distances;
}

struct SegmentSums {
  std::size_t pairs = 0;
  double translation_ratio = 0.0;   // sum of |t_E| / L
  double rotation_deg_per_m = 0.0;  // sum of angle(R_E) / L
};

}  // namespace

std::string KittiRelativeError::no_segments_reason() const {
  if (has_segments()) return {};
  char buf[200];
  std::snprintf(buf, sizeof buf,
                "no segments: the ground-truth path (%.1f m) is not longer than the shortest segment (%.0f m)",
                path_length_m, kKittiSegmentLengthsM.front());
  return buf;
}

KittiRelativeError kitti_relative_error(const std::vector<Eigen::Isometry3d>& gt_T_w_c,
                                        const std::vector<Eigen::Isometry3d>& est_T_w_c) {
  if (gt_T_w_c.size() != est_T_w_c.size())
    throw Error("KITTI relative error: " + std::to_string(gt_T_w_c.size()) + " ground-truth poses but " +
                std::to_string(est_T_w_c.size()) + " estimated poses (expected one estimate per ground-truth pose)");
  const std::vector<double> distances = distances_along(gt_T_w_c);

  std::array<SegmentSums, kKittiSegmentLengthsM.size()> sums{};
  for (std::size_t first = 0; first < gt_T_w_c.size(); first += kKittiFirstPoseStep) {
    for (std::size_t k = 0; k < kKittiSegmentLengthsM.size(); ++k) {
      const double length = kKittiSegmentLengthsM[k];
      // The distances never decrease: the first pose more than `length` on.
      const auto end = std::upper_bound(distances.begin() + static_cast<std::ptrdiff_t>(first), distances.end(),
                                        distances[first] + length);
      if (end == distances.end()) break;  // the longer lengths end even later
      const auto last = static_cast<std::size_t>(end - distances.begin());
      const Eigen::Isometry3d gt_motion = gt_T_w_c[first].inverse() * gt_T_w_c[last];
      const Eigen::Isometry3d est_motion = est_T_w_c[first].inverse() * est_T_w_c[last];
      const Eigen::Isometry3d error = gt_motion.inverse() * est_motion;
      SegmentSums& s = sums[k];
      ++s.pairs;
      s.translation_ratio += error.translation().norm() / length;
      // rotation_angle_deg: through the quaternion, where the devkit's acos
      // of the trace loses precision at the small angles of a good estimate.
      s.rotation_deg_per_m += rotation_angle_deg(error.linear()) / length;
    }
  }

  KittiRelativeError result;
  result.path_length_m = distances.empty() ? 0.0 : distances.back();
  double translation_ratio = 0.0, rotation_deg_per_m = 0.0;
  for (std::size_t k = 0; k < kKittiSegmentLengthsM.size(); ++k) {
    const SegmentSums& s = sums[k];
    if (s.pairs == 0) continue;
    const double n = static_cast<double>(s.pairs);
    result.per_length.push_back(
        {kKittiSegmentLengthsM[k], s.pairs, 100.0 * s.translation_ratio / n, 100.0 * s.rotation_deg_per_m / n});
    result.pairs += s.pairs;
    translation_ratio += s.translation_ratio;
    rotation_deg_per_m += s.rotation_deg_per_m;
  }
  if (result.has_segments()) {
    const double n = static_cast<double>(result.pairs);
    result.translation_percent = 100.0 * translation_ratio / n;
    result.rotation_deg_per_100m = 100.0 * rotation_deg_per_m / n;
  }
  return result;
}

KittiRelativeError kitti_relative_error_after_alignment(const Trajectory& gt, const Trajectory& est,
                                                        const TrajectoryEvaluation& evaluation) {
  std::vector<Eigen::Isometry3d> gt_T_w_c, aligned_est_T_w_c;
  gt_T_w_c.reserve(evaluation.associated.size());
  aligned_est_T_w_c.reserve(evaluation.associated.size());
  for (const AssociatedPair& pair : evaluation.associated) {
    if (pair.gt_index >= gt.size() || pair.est_index >= est.size())
      throw Error("internal: KITTI relative error of an evaluation of other trajectories");
    gt_T_w_c.push_back(gt[pair.gt_index].T_w_c);
    aligned_est_T_w_c.push_back(evaluation.alignment.apply_to_pose(est[pair.est_index].T_w_c));
  }
  return kitti_relative_error(gt_T_w_c, aligned_est_T_w_c);
}

Json to_json(const KittiRelativeError& error) {
  // NaN is not JSON: figures without segments are null.
  const auto figure = [&](double value) { return error.has_segments() ? Json(value) : Json(); };
  Json j = Json::object();
  j["path_length_m"] = error.path_length_m;
  j["pairs"] = error.pairs;
  j["translation_percent"] = figure(error.translation_percent);
  j["rotation_deg_per_100m"] = figure(error.rotation_deg_per_100m);
  Json per_length = Json::array();
  for (const KittiLengthError& e : error.per_length) {
    Json length = Json::object();
    length["length_m"] = e.length_m;
    length["pairs"] = e.pairs;
    length["translation_percent"] = e.translation_percent;
    length["rotation_deg_per_100m"] = e.rotation_deg_per_100m;
    per_length.push_back(length);
  }
  j["per_length"] = per_length;
  if (!error.has_segments()) j["no_segments"] = error.no_segments_reason();
  return j;
}

}  // namespace facadeslam
