#pragma once
// Pinhole + radial-tangential calibration with OpenCV (Zhang's closed-form
// start, then Levenberg-Marquardt over intrinsics, k1 k2 p1 p2 k3 and the
// board poses): cv::calibrateCamera.
#include <vector>

#include <opencv2/core.hpp>

#include "calib/board.hpp"
#include "calib/calibration_result.hpp"
#include "calib/view_collection.hpp"

namespace facadeslam::calib {

// Throws Error when OpenCV fails or returns a camera that is not usable
// (non-finite values, focal lengths <= 0).
CalibrationResult calibrate_pinhole(const std::vector<AcceptedView>& views, const cv::Size& image_size,
                                    const BoardSpec& board, const FitOptions& options = {});

}  // namespace facadeslam::calib
