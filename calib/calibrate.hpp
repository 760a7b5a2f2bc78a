#pragma once
// The whole calibration job behind `facadeslam calibrate`: list the images
// of a folder, find the board in each and drop unusable views, fit the
// chosen camera model, and measure residuals and coverage. Writing the
// outputs (camera YAML, PNG, JSON) and printing are separate steps
// (calibration_report.hpp), so tests can inspect the run in memory.
#include <filesystem>
#include <optional>

#include "calib/board.hpp"
#include "calib/calibration_result.hpp"
#include "calib/coverage.hpp"
#include "calib/view_collection.hpp"
#include "calib/view_quality.hpp"

namespace facadeslam::calib {

struct CalibrationRequest {
  std::filesystem::path images;  // folder of .png/.jpg/.jpeg/.bmp chessboard images
  BoardSpec board;
  ModelKind model = ModelKind::pinhole;
  FitOptions fit;
  QualityThresholds quality;
};

struct CalibrationRun {
  CalibrationRequest request;
  ViewCollection views;
  CalibrationResult result;
  CoverageFigures coverage;
  // For an ATAN run, the RMS of the pinhole fit it started from (to compare
  // the models); absent for a pinhole run.
  std::optional<double> pinhole_rms_px;
};

// Throws Error on every user-facing problem (see collect_views and the
// model fits).
CalibrationRun run_calibration(const CalibrationRequest& request);

}  // namespace facadeslam::calib
