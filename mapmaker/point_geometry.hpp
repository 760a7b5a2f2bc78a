#pragma once
// The geometry of a map point seen from its source keyframe: its position and
// the world offsets of one source-level pixel right and down on a patch
// facing that camera (what the tracker warps patches with). Used when a point
// is created and whenever bundle adjustment moves it or its source keyframe.
#include "core/camera/camera.hpp"
#include "core/lie/se3.hpp"
#include "core/map/map_point.hpp"

namespace facadeslam {

// Geometry for a point at `p_w` whose patch is at `source` in a keyframe with
// pose `T_src_w`. The point's depth is its z in the source camera.
PointGeometry source_geometry(const Camera& camera, const SE3d& T_src_w, const PatchSource& source,
                              const Eigen::Vector3d& p_w);

}  // namespace facadeslam
