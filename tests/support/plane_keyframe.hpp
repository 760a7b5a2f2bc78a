#pragma once
// A keyframe of the rendered plane (rendered_plane.hpp) added to a Map: its
// pyramid with corners, its small blurry image, and the plane's depth as the
// keyframe's scene depth (mean plane_depth, sigma 0.1 m).
#include <memory>

#include "core/map/map.hpp"
#include "tests/support/rendered_plane.hpp"

namespace facadeslam::test {

std::shared_ptr<KeyFrame> add_plane_keyframe(Map& map, const RenderedPlane& plane, const Camera& camera,
                                             const SE3d& T_c_w);

}  // namespace facadeslam::test
