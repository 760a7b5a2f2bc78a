#pragma once
// The KITTI odometry benchmark's relative errors (the devkit's
// evaluate_odometry.cpp, Geiger et al. CVPR 2012), as the benchmark's table
// reports them: translation error in % and rotation error in deg per 100 m,
// over path segments of 100, 200, ... 800 m.
//
// Distances are measured along the ground truth. From every 10th pose (the
// devkit's step: one second of KITTI's 10 Hz) and for each segment length L,
// the segment ends at the first pose whose distance from the first pose is
// more than L (the devkit's strict comparison). Its error is the motion
// error E = (G_first^-1 G_last)^-1 (A_first^-1 A_last): |t_E| / L and
// angle(R_E) / L. Segment lengths the path is too short for are left out.
// Figures per length are means over that length's segments; the overall
// figures are means over all segments of all lengths (the devkit's
// stats.txt, which weighs a length by its number of segments).
//
// The devkit compares the raw poses: a monocular estimate, whose scale is
// arbitrary, is first aligned to the ground truth with Sim(3) (Umeyama on
// positions, as for the ATE: kitti_relative_error_after_alignment). A rigid
// alignment cancels out of E; only the scale changes the figures.
#include <array>
#include <cstddef>
#include <limits>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "core/trajectory/metrics.hpp"
#include "core/trajectory/trajectory.hpp"
#include "core/util/json.hpp"

namespace facadeslam {

inline constexpr std::array<double, 8> kKittiSegmentLengthsM = {100, 200, 300, 400, 500, 600, 700, 800};
inline constexpr std::size_t kKittiFirstPoseStep = 10;

struct KittiLengthError {
  double length_m = 0.0;
  std::size_t pairs = 0;               // segments (first pose, last pose) of this length
  double translation_percent = 0.0;    // mean |t_E| / L, x 100
  double rotation_deg_per_100m = 0.0;  // mean angle(R_E) / L, degrees x 100
};

struct KittiRelativeError {
  double path_length_m = 0.0;  // along the ground-truth poses compared
  // The segment lengths the path is long enough for, shortest first.
  std::vector<KittiLengthError> per_length;
  // Over all segments; 0 pairs (a path shorter than 100 m): NaN figures.
  std::size_t pairs = 0;
  double translation_percent = std::numeric_limits<double>::quiet_NaN();
  double rotation_deg_per_100m = std::numeric_limits<double>::quiet_NaN();

  bool has_segments() const { return pairs > 0; }
  // Why there are no segments, for reports (empty when there are some).
  std::string no_segments_reason() const;
};

// Of poses that correspond by index (pose i of the estimate was taken at
// pose i of the ground truth), as they are: no alignment. Throws Error when
// the two lists differ in length.
KittiRelativeError kitti_relative_error(const std::vector<Eigen::Isometry3d>& gt_T_w_c,
                                        const std::vector<Eigen::Isometry3d>& est_T_w_c);

// Of the pose pairs `evaluation` associated (evaluate_trajectory(gt, est)),
// in estimate-time order, with the estimate aligned as `evaluation` aligned
// it (Sim(3) or SE(3)): the step of 10 is then 10 associated pairs.
KittiRelativeError kitti_relative_error_after_alignment(const Trajectory& gt, const Trajectory& est,
                                                        const TrajectoryEvaluation& evaluation);

// {"path_length_m", "pairs", "translation_percent", "rotation_deg_per_100m"
// (null without segments), "per_length": [{"length_m", "pairs",
// "translation_percent", "rotation_deg_per_100m"}, ...]} and, without
// segments, "no_segments": the reason.
Json to_json(const KittiRelativeError& error);

}  // namespace facadeslam
