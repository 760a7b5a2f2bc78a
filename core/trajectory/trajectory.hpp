#pragma once
// A trajectory as the evaluator sees it: camera poses in the world frame,
// each with the time it was taken, in time order.
#include <vector>

#include <Eigen/Geometry>

namespace facadeslam {

struct StampedPose {
  double timestamp = 0.0;                                   // seconds
  Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();  // camera -> world
};

using Trajectory = std::vector<StampedPose>;

// The trajectory once per offset, each copy shifted by its offset in time
// (the ground truth of a looped replay: ReadStats::pass_time_offsets_s).
// Where a copy would reach back into the time the previous one covers (a
// ground truth longer than the frames), its overlapping poses are dropped,
// so the result stays in time order. No offsets: the trajectory as it is.
inline Trajectory repeat_trajectory(const Trajectory& trajectory, const std::vector<double>& offsets) {
  if (offsets.empty()) return trajectory;
  Trajectory out;
  out.reserve(trajectory.size() * offsets.size());
  for (const double offset : offsets)
    for (StampedPose pose : trajectory) {
      pose.timestamp += offset;
      if (out.empty() || pose.timestamp > out.back().timestamp || offset == offsets.front()) out.push_back(pose);
    }
  return out;
}

}  // namespace facadeslam
