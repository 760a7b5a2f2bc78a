#pragma once
// Top views of a trajectory against ground truth: which two world axes to
// plot, and the PNG (`evaluate trajectory --plot`, `replay --gt`).
#include <array>
#include <filesystem>
#include <string>
#include <string_view>

#include "core/trajectory/metrics.hpp"
#include "core/trajectory/trajectory.hpp"

namespace facadeslam {

// Axis indices (0 = x, 1 = y, 2 = z) of the plane named "xy", "xz" or "yz";
// for "auto", the two axes along which `trajectory`'s positions spread most,
// which is the ground plane both for camera-style world frames (y down:
// KITTI, a map started from a camera) and for z-up frames (the synthetic
// streets), since a hand-held or vehicle path mostly keeps its height.
// Throws Error for any other name.
std::array<int, 2> top_view_axes(std::string_view plane, const Trajectory& trajectory);

// Writes the ground truth and the aligned estimate of `evaluation` seen from
// above (axes from top_view_axes(plane, gt)) as a PNG, atomically. The
// ground truth is drawn in full over the time the estimate covers (not only
// at the associated poses), so that sparse keyframe estimates are seen
// against the real path. `alignment` names the alignment in the title.
void save_top_view_png(const std::filesystem::path& path, const Trajectory& gt, const TrajectoryEvaluation& evaluation,
                       std::string_view plane = "auto", std::string_view alignment = "sim3",
                       double max_dt = kDefaultMaxTimeDifference);

}  // namespace facadeslam
