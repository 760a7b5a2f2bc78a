#pragma once
// A picture of the calibration for the user: every detected corner drawn at
// its image position over a blank frame of the camera's size, its residual
// vector (observed - projected) magnified, one colour per view, the
// coverage grid with covered cells tinted, and a side panel with the figures
// and the per-view RMS. Uncovered cells show where the distortion estimate
// is extrapolated; long or aligned residual vectors show a poor fit.
#include <filesystem>

#include <opencv2/core.hpp>

#include "calib/calibration_result.hpp"
#include "calib/coverage.hpp"
#include "calib/view_collection.hpp"

namespace facadeslam::calib {

// Residual magnification: 50 unless the largest residual would then be
// drawn longer than a tenth of the image diagonal, in which case the largest
// 1-2-5 value that keeps it so.
double residual_scale(const CalibrationResult& result, const cv::Size& image_size);

// 8-bit BGR; the frame is drawn 1:1 (2:1, 3:1, ... for images narrower than
// 640 px) with a 280 px panel on the right.
cv::Mat render_residual_plot(const ViewCollection& views, const CalibrationResult& result,
                             const CoverageFigures& coverage);

// Renders and writes a PNG atomically; the name must end in ".png".
void save_residual_plot(const std::filesystem::path& path, const ViewCollection& views, const CalibrationResult& result,
                        const CoverageFigures& coverage);

}  // namespace facadeslam::calib
