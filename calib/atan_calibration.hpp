#pragma once
// PTAM's ATAN/FOV camera fitted with Ceres: fx, fy, cx, cy, w and every
// view's board pose T_c_b (on SE3Manifold) jointly minimise the squared
// reprojection error of the detected corners.
//
// Start: the pinhole + radial-tangential solution. Its poses carry over;
// w comes from its k1 (for small radii the ATAN model bends like
// k1 = -(2 tan(w/2))^2 / 3), and the focal lengths are divided by the
// ATAN model's slope at the centre, 2 tan(w/2) / w, so the image scale is
// unchanged. w = 0 is a stationary point of the cost (the model is even
// in w), so the start is never exactly there.
#include <vector>

#include <opencv2/core.hpp>

#include "calib/board.hpp"
#include "calib/calibration_result.hpp"
#include "calib/view_collection.hpp"

namespace facadeslam::calib {

// `pinhole_start` must be a pinhole result for the same views. Throws Error
// when Ceres finds no usable solution.
CalibrationResult calibrate_atan(const std::vector<AcceptedView>& views, const CalibrationResult& pinhole_start,
                                 const BoardSpec& board, const FitOptions& options = {});

// The start values [fx, fy, cx, cy, w] derived from a pinhole camera (see
// above); exposed for the tests.
std::vector<double> atan_start_from_pinhole(const PinholeRadTan& pinhole, bool tie_focal);

}  // namespace facadeslam::calib
