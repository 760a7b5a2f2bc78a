#pragma once
// Which two world axes a top view of a trajectory plots.
#include <array>
#include <string_view>

#include "core/trajectory/trajectory.hpp"

namespace facadeslam {

// Axis indices (0 = x, 1 = y, 2 = z) of the plane named "xy", "xz" or "yz";
// for "auto", the two axes along which `trajectory`'s positions spread most,
// which is the ground plane both for camera-style world frames (y down:
// KITTI, a map started from a camera) and for z-up frames (the synthetic
// streets), since a hand-held or vehicle path mostly keeps its height.
// Throws Error for any other name.
std::array<int, 2> top_view_axes(std::string_view plane, const Trajectory& trajectory);

}  // namespace facadeslam
