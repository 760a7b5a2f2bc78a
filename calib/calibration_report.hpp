#pragma once
// Presenting a calibration: the table printed on the terminal, the JSON
// report, and the camera YAML (core/camera's format, with a provenance
// header that carries no date, so reruns on the same images give identical
// files).
#include <filesystem>
#include <string>

#include "calib/calibrate.hpp"
#include "core/util/json.hpp"

namespace facadeslam::calib {

// Multi-line text: inputs, rejected images with reasons, per-image RMS,
// intrinsics, RMS and coverage, plus notes when the coverage is poor.
std::string format_report(const CalibrationRun& run);

// Everything of format_report() as JSON (numbers unrounded).
Json report_json(const CalibrationRun& run);

// The '#' comment header of the camera file: tool, RMS, image counts,
// board, model options.
std::string camera_file_header(const CalibrationRun& run);

// Writes the camera with save_camera() after checking that load_camera()
// accepts it (a fit whose distortion folds back inside the image, or whose
// ATAN field does not reach the corners, would give a file nothing can
// load). On failure throws Error naming `path` and leaves it untouched.
void write_camera_file(const std::filesystem::path& path, const CalibrationRun& run);

}  // namespace facadeslam::calib
