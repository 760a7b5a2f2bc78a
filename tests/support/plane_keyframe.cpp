#include "tests/support/plane_keyframe.hpp"

namespace facadeslam::test {

std::shared_ptr<KeyFrame> add_plane_keyframe(Map& map, const RenderedPlane& plane, const Camera& camera,
                                             const SE3d& T_c_w) {
  auto pyramid = std::make_shared<const ImagePyramid>(render(plane, camera, T_c_w));
  auto kf = std::make_shared<KeyFrame>(map.new_keyframe_id(), Frame{0, 0.0, cv::Mat(), {}, pyramid}, T_c_w);
  map.add_keyframe(kf);
  map.update([&](MapEditor& edit) { edit.set_depth_stats(*kf, plane.plane_depth, 0.1); });
  return kf;
}

}  // namespace facadeslam::test
