#include "core/trajectory/metrics.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>

#include <Eigen/Geometry>

#include "core/util/angles.hpp"
#include "core/util/error.hpp"

namespace facadeslam {
namespace {

double rms(const std::vector<double>& values) {
  double sum = 0.0;
  for (const double v : values) sum += v * v;
  return std::sqrt(sum / static_cast<double>(values.size()));
}

}  // namespace

double rotation_angle_deg(const Eigen::Matrix3d& R) {
  // Through the quaternion: acos of the trace loses precision at small angles.
  return rad_to_deg(Eigen::AngleAxisd(Eigen::Quaterniond(R).normalized()).angle());
}

AlignmentMode parse_alignment_mode(const std::string& name) {
  if (name == "sim3") return AlignmentMode::sim3;
  if (name == "se3") return AlignmentMode::se3;
  throw Error("alignment: expected 'sim3' or 'se3', got '" + name + "'");
}

std::string to_string(AlignmentMode mode) { return mode == AlignmentMode::sim3 ? "sim3" : "se3"; }

ErrorStatistics error_statistics(std::vector<double> errors) {
  if (errors.empty()) throw Error("internal: error statistics of an empty list");
  ErrorStatistics s;
  s.rmse = rms(errors);
  double sum = 0.0;
  for (const double e : errors) sum += e;
  s.mean = sum / static_cast<double>(errors.size());
  std::sort(errors.begin(), errors.end());
  const std::size_t mid = errors.size() / 2;
  s.median = errors.size() % 2 == 1 ? errors[mid] : 0.5 * (errors[mid - 1] + errors[mid]);
  s.max = errors.back();
  return s;
}

TrajectoryEvaluation evaluate_trajectory(const Trajectory& gt, const Trajectory& est,
                                         const EvaluationOptions& options) {
  const auto pairs = associate_by_time(gt, est, options.max_dt);
  if (pairs.size() < 3) {
    char buf[240];
    std::snprintf(buf, sizeof buf,
                  "only %zu of %zu estimated poses have a ground-truth pose within %g s (expected at "
                  "least 3: do the timestamps of both files use the same clock?)",
                  pairs.size(), est.size(), options.max_dt);
    throw Error(buf);
  }
  if (options.rpe_delta == 0 || options.rpe_delta >= pairs.size())
    throw Error("RPE delta must be between 1 and " + std::to_string(pairs.size() - 1) +
                " (the number of associated pairs minus one), got " + std::to_string(options.rpe_delta));

  TrajectoryEvaluation result;
  result.pairs = pairs.size();
  result.associated = pairs;

  std::vector<Eigen::Vector3d> est_positions;
  est_positions.reserve(pairs.size());
  for (const auto& p : pairs) {
    result.timestamps.push_back(est[p.est_index].timestamp);
    result.gt_positions.push_back(gt[p.gt_index].T_w_c.translation());
    est_positions.push_back(est[p.est_index].T_w_c.translation());
  }
  result.alignment = umeyama_alignment(est_positions, result.gt_positions, options.alignment == AlignmentMode::sim3);
  result.scale = result.alignment.scale;

  // ATE
  std::vector<double> position_errors;
  position_errors.reserve(pairs.size());
  for (std::size_t i = 0; i < pairs.size(); ++i) {
    result.aligned_est_positions.push_back(result.alignment.apply(est_positions[i]));
    position_errors.push_back((result.gt_positions[i] - result.aligned_est_positions.back()).norm());
  }
  const auto ate = error_statistics(position_errors);
  result.ate_rmse_m = ate.rmse;
  result.ate_mean_m = ate.mean;
  result.ate_median_m = ate.median;
  result.ate_max_m = ate.max;

  // RPE: E = (G_i^-1 G_j)^-1 (A_i^-1 A_j) with A the aligned estimate.
  std::vector<double> trans_errors, rot_errors;
  for (std::size_t i = 0; i + options.rpe_delta < pairs.size(); ++i) {
    const std::size_t j = i + options.rpe_delta;
    const Eigen::Isometry3d gt_motion = gt[pairs[i].gt_index].T_w_c.inverse() * gt[pairs[j].gt_index].T_w_c;
    const Eigen::Isometry3d est_motion = result.alignment.apply_to_pose(est[pairs[i].est_index].T_w_c).inverse() *
                                         result.alignment.apply_to_pose(est[pairs[j].est_index].T_w_c);
    const Eigen::Isometry3d error = gt_motion.inverse() * est_motion;
    trans_errors.push_back(error.translation().norm());
    rot_errors.push_back(rotation_angle_deg(error.linear()));
  }
  result.rpe_trans_rmse_m = rms(trans_errors);
  result.rpe_rot_rmse_deg = rms(rot_errors);

  // Path length of the ground truth over the associated poses, in time order
  // (the pairs are in estimate order, which may differ by a swap).
  std::vector<std::size_t> gt_indices;
  for (const auto& p : pairs) gt_indices.push_back(p.gt_index);
  std::sort(gt_indices.begin(), gt_indices.end());
  for (std::size_t k = 1; k < gt_indices.size(); ++k)
    result.path_length_m += (gt[gt_indices[k]].T_w_c.translation() - gt[gt_indices[k - 1]].T_w_c.translation()).norm();
  result.ate_percent_of_path = result.path_length_m > 0.0 ? 100.0 * result.ate_rmse_m / result.path_length_m
                                                          : std::numeric_limits<double>::quiet_NaN();
  return result;
}

Json to_json(const TrajectoryEvaluation& e) {
  Json j = Json::object();
  j["pairs"] = e.pairs;
  j["scale"] = e.scale;
  j["ate_rmse_m"] = e.ate_rmse_m;
  j["ate_mean_m"] = e.ate_mean_m;
  j["ate_median_m"] = e.ate_median_m;
  j["ate_max_m"] = e.ate_max_m;
  j["rpe_trans_rmse_m"] = e.rpe_trans_rmse_m;
  j["rpe_rot_rmse_deg"] = e.rpe_rot_rmse_deg;
  j["path_length_m"] = e.path_length_m;
  j["ate_percent_of_path"] = e.ate_percent_of_path;
  return j;
}

}  // namespace facadeslam
