#pragma once
// Reading and writing trajectory files.
//
// TUM:   `timestamp tx ty tz qx qy qz qw` per line (camera -> world), `#`
//        comments and blank lines allowed; quaternions are normalised.
// KITTI: 12 numbers per line, the row-major 3x4 matrix [R | t] of T_w_c; the
//        timestamps come from a separate times file (one number per line),
//        from a frame rate (line i at i / rate), or without either are the
//        line index (0, 1, 2, ...): two such files pair line by line.
//
// Every failure throws facadeslam::Error naming the file (and line).
#include <filesystem>
#include <string>

#include "core/trajectory/trajectory.hpp"

namespace facadeslam {

enum class TrajectoryFormat {
  auto_detect,  // by the number of columns of the first pose line: 8 TUM, 12 KITTI
  tum,
  kitti,
};

// "auto", "tum" or "kitti"; anything else throws Error.
TrajectoryFormat parse_trajectory_format(const std::string& name);
std::string to_string(TrajectoryFormat format);

// Reads a trajectory. `times_path` (KITTI only) holds one timestamp per pose;
// without it, a KITTI file's line i is at i / `rate_hz` seconds (a rate of 0:
// at i). Timestamps must not decrease (repeats are kept: real TUM ground
// truth has them); an empty file is an error, and so is a rate that is
// negative or not finite.
Trajectory read_trajectory(const std::filesystem::path& path, TrajectoryFormat format = TrajectoryFormat::auto_detect,
                           const std::filesystem::path& times_path = {}, double rate_hz = 0.0);

// TUM or KITTI, by the number of columns of the first pose line (8 or 12).
// Errors as read_trajectory's for that line (missing file, no poses, another
// column count).
TrajectoryFormat detect_trajectory_format(const std::filesystem::path& path);

// Writes TUM format atomically: timestamps with 9 decimals (nanoseconds),
// positions and quaternions with 15 significant digits.
void write_tum_trajectory(const std::filesystem::path& path, const Trajectory& trajectory);

}  // namespace facadeslam
