#pragma once
// A trajectory as the evaluator sees it: camera poses in the world frame,
// each with the time it was taken, in time order.
#include <vector>

#include <Eigen/Geometry>

namespace facadeslam {

struct StampedPose {
  double timestamp = 0.0;  // seconds
  Eigen::Isometry3d T_w_c = Eigen::Isometry3d::Identity();  // camera -> world
};

using Trajectory = std::vector<StampedPose>;

}  // namespace facadeslam
