#include "calib/calibration_result.hpp"

#include <cmath>

#include "core/util/error.hpp"

namespace facadeslam::calib {

ModelKind parse_model_kind(const std::string& text) {
  if (text == "pinhole") return ModelKind::pinhole;
  if (text == "atan") return ModelKind::atan;
  throw Error("camera model '" + text + "': expected pinhole (OpenCV radial-tangential) or atan (PTAM FOV model)");
}

std::string model_kind_name(ModelKind kind) { return kind == ModelKind::pinhole ? "pinhole" : "atan"; }

CalibrationResult evaluate_calibration(const Camera& camera, std::vector<SE3d> T_c_b,
                                       const std::vector<AcceptedView>& views, const BoardSpec& board) {
  if (T_c_b.size() != views.size()) throw Error("evaluate_calibration: expected one board pose per view");
  CalibrationResult result{camera, std::move(T_c_b), {}, {}, 0.0};
  const int corner_count = board.corner_count();
  double total_squared = 0.0;
  std::size_t total_count = 0;
  for (std::size_t v = 0; v < views.size(); ++v) {
    std::vector<Eigen::Vector2d> residuals;
    residuals.reserve(corner_count);
    double view_squared = 0.0;
    for (int k = 0; k < corner_count; ++k) {
      const Eigen::Vector2d projected = camera.project(result.T_c_b[v] * board_corner(board, k));
      const Eigen::Vector2d observed(views[v].corners[k].x, views[v].corners[k].y);
      residuals.push_back(observed - projected);
      view_squared += residuals.back().squaredNorm();
    }
    result.view_rms_px.push_back(std::sqrt(view_squared / corner_count));
    result.residuals.push_back(std::move(residuals));
    total_squared += view_squared;
    total_count += corner_count;
  }
  result.rms_px = total_count > 0 ? std::sqrt(total_squared / static_cast<double>(total_count)) : 0.0;
  return result;
}

}  // namespace facadeslam::calib
