#pragma once
// What a calibration produces, whichever model was fitted: the camera, the
// board pose of every view and the reprojection residuals that the report,
// the plot and the tests read.
//
// Residual = observed corner - projected board corner, in pixels. RMS is
// over corners (sqrt of the mean squared residual LENGTH), the figure
// cv::calibrateCamera returns, so the two can be compared directly.
#include <string>
#include <vector>

#include <Eigen/Core>

#include "calib/board.hpp"
#include "calib/view_collection.hpp"
#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"

namespace facadeslam::calib {

enum class ModelKind { pinhole, atan };

// "pinhole" | "atan" (the names used by --model and the camera YAML);
// throws Error naming the text otherwise.
ModelKind parse_model_kind(const std::string& text);
std::string model_kind_name(ModelKind kind);

// Solver choices shared by both models.
struct FitOptions {
  // fx = fy (CALIB_FIX_ASPECT_RATIO with aspect 1, as OpenCV's sample
  // calibration does); default: both free.
  bool fix_aspect = false;
  // Pinhole only: keep k3 = 0. With few or central views the sixth-order
  // term is poorly constrained and can make the polynomial fold back inside
  // the image corners.
  bool fix_k3 = false;
};

struct CalibrationResult {
  Camera camera;
  std::vector<SE3d> T_c_b;                              // board -> camera, per view
  std::vector<std::vector<Eigen::Vector2d>> residuals;  // per view, per corner, pixels
  std::vector<double> view_rms_px;                      // per view
  double rms_px = 0.0;                                  // over all corners
};

// Projects the board with `camera` at the given poses and fills in the
// residuals and RMS figures.
CalibrationResult evaluate_calibration(const Camera& camera, std::vector<SE3d> T_c_b,
                                       const std::vector<AcceptedView>& views, const BoardSpec& board);

}  // namespace facadeslam::calib
