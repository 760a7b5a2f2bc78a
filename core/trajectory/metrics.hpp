#pragma once
// Trajectory accuracy against ground truth, as the TUM RGB-D benchmark and
// evo define it:
//  - ATE (absolute trajectory error): distances between ground-truth and
//    estimated positions after aligning the estimate (Umeyama on positions,
//    Sim(3) for monocular estimates, SE(3) otherwise).
//  - RPE (relative pose error): the error of the motion between pose i and
//    pose i + delta, in translation (m) and rotation (deg). A rigid alignment
//    cancels out of it, but the Sim(3) scale does not: it rescales the
//    estimated motions, so RPE is computed on the aligned estimate.
#include <cstddef>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "core/trajectory/alignment.hpp"
#include "core/trajectory/association.hpp"
#include "core/trajectory/trajectory.hpp"
#include "core/util/json.hpp"

namespace facadeslam {

enum class AlignmentMode { se3, sim3 };

// "se3" or "sim3"; anything else throws Error.
AlignmentMode parse_alignment_mode(const std::string& name);
std::string to_string(AlignmentMode mode);

struct EvaluationOptions {
  AlignmentMode alignment = AlignmentMode::sim3;
  double max_dt = kDefaultMaxTimeDifference;  // seconds, for the association
  std::size_t rpe_delta = 1;                  // RPE over pairs i, i + delta (in associated pairs)
};

struct ErrorStatistics {
  double rmse = 0.0, mean = 0.0, median = 0.0, max = 0.0;
};

// Of a non-empty list of non-negative errors (throws Error if empty).
ErrorStatistics error_statistics(std::vector<double> errors);

// The angle of the rotation R, degrees in [0, 180].
double rotation_angle_deg(const Eigen::Matrix3d& R);

struct TrajectoryEvaluation {
  std::size_t pairs = 0;  // associated pose pairs
  double scale = 1.0;     // Sim(3) scale (1 for SE(3))
  double ate_rmse_m = 0.0;
  double ate_mean_m = 0.0;
  double ate_median_m = 0.0;
  double ate_max_m = 0.0;
  double rpe_trans_rmse_m = 0.0;
  double rpe_rot_rmse_deg = 0.0;
  double path_length_m = 0.0;        // of the associated ground-truth poses
  double ate_percent_of_path = 0.0;  // 100 * ate_rmse_m / path_length_m

  // For plots and further analysis: the alignment (gt ≈ s R est + t) and,
  // per associated pair in estimate-time order, the pose indices, the
  // estimate's timestamp, the ground-truth position and the aligned estimate
  // position.
  Sim3Alignment alignment;
  std::vector<AssociatedPair> associated;
  std::vector<double> timestamps;
  std::vector<Eigen::Vector3d> gt_positions;
  std::vector<Eigen::Vector3d> aligned_est_positions;
};

// Associates, aligns and measures. Throws Error when fewer than 3 pairs
// associate, the alignment is degenerate, or rpe_delta is 0 or not smaller
// than the number of pairs.
TrajectoryEvaluation evaluate_trajectory(const Trajectory& gt, const Trajectory& est,
                                         const EvaluationOptions& options = {});

// The ten figures, with the field names as keys (pairs ... ate_percent_of_path).
Json to_json(const TrajectoryEvaluation& evaluation);

}  // namespace facadeslam
