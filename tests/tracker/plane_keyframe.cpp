#include "tests/tracker/plane_keyframe.hpp"

#include "tracker/reloc/small_blurry_image.hpp"

namespace facadeslam::tracker::test {

std::shared_ptr<KeyFrame> add_plane_keyframe(Map& map, const RenderedPlane& plane, const Camera& camera,
                                             const SE3d& T_c_w) {
  auto pyramid = std::make_shared<const ImagePyramid>(render(plane, camera, T_c_w));
  auto kf = std::make_shared<KeyFrame>(map.new_keyframe_id(), 0.0, T_c_w, pyramid, cv::Mat(),
                                       make_small_blurry_image(*pyramid));
  kf->set_depth_stats(plane.plane_depth, 0.1);
  map.add_keyframe(kf);
  return kf;
}

}  // namespace facadeslam::tracker::test
