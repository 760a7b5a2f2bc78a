#include "core/trajectory/top_view.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "core/plot/line_plot.hpp"
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

void save_top_view_png(const std::filesystem::path& path, const Trajectory& gt, const TrajectoryEvaluation& e,
                       std::string_view plane, std::string_view alignment, double max_dt) {
  if (e.timestamps.empty()) throw Error(path.string() + ": no associated poses to plot");
  const auto [u, v] = top_view_axes(plane, gt);
  plot::LinePlot figure;
  char title[160];
  std::snprintf(title, sizeof title, "Top view, %.*s alignment: ATE RMSE %.4f m over %zu poses",
                static_cast<int>(alignment.size()), alignment.data(), e.ate_rmse_m, e.pairs);
  figure.set_title(title);
  const char axis_names[] = "xyz";
  figure.set_x_label(std::string(1, axis_names[u]).append(" [m]"));
  figure.set_y_label(std::string(1, axis_names[v]).append(" [m]"));
  figure.set_equal_axes(true);

  std::vector<double> gt_u, gt_v, est_u, est_v;
  const double first = e.timestamps.front() - max_dt, last = e.timestamps.back() + max_dt;
  for (const auto& pose : gt)
    if (pose.timestamp >= first && pose.timestamp <= last) {
      gt_u.push_back(pose.T_w_c.translation()[u]);
      gt_v.push_back(pose.T_w_c.translation()[v]);
    }
  for (const auto& p : e.aligned_est_positions) {
    est_u.push_back(p[u]);
    est_v.push_back(p[v]);
  }
  plot::SeriesStyle gt_style;
  gt_style.colour = cv::Scalar(70, 70, 70);
  figure.add_series("ground truth", gt_u, gt_v, gt_style);
  plot::SeriesStyle est_style;
  est_style.markers = e.pairs <= 300;  // keyframe trajectories: show each pose
  est_style.colour = plot::series_colour(0);
  est_style.thickness = 1;  // the ground truth stays visible underneath
  figure.add_series("estimate (aligned)", est_u, est_v, est_style);
  figure.save_png(path);
}

}  // namespace facadeslam
