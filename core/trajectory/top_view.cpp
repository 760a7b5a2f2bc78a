#include "core/trajectory/top_view.hpp"

#include <string>

#include "core/util/error.hpp"

namespace facadeslam {

std::array<int, 2> top_view_axes(std::string_view plane, const Trajectory& trajectory) {
  if (plane == "xy") return {0, 1};
  if (plane == "xz") return {0, 2};
  if (plane == "yz") return {1, 2};
  if (plane != "auto")
    throw Error(std::string("top view plane must be auto, xy, xz or yz, not '").append(plane).append("'"));
  Eigen::Vector3d mean = Eigen::Vector3d::Zero(), spread = Eigen::Vector3d::Zero();
  for (const auto& pose : trajectory) mean += pose.T_w_c.translation();
  if (!trajectory.empty()) mean /= static_cast<double>(trajectory.size());
  for (const auto& pose : trajectory) spread += (pose.T_w_c.translation() - mean).cwiseAbs2();
  int flattest = 2;  // an empty or static trajectory: the x-y plane
  if (spread.maxCoeff() > 0) spread.minCoeff(&flattest);
  if (flattest == 0) return {1, 2};
  if (flattest == 1) return {0, 2};
  return {0, 1};
}

}  // namespace facadeslam
