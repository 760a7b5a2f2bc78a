#include "core/map/keyframe.hpp"

#include "core/image/small_blurry_image.hpp"
#include "core/util/error.hpp"
#include "core/util/assert.hpp"

namespace facadeslam {

KeyFrame::KeyFrame(Id id, const Frame& frame, const SE3d& T_c_w, Measurements measurements)
    : id_(id),
      frame_index_(frame.index),
      timestamp_(frame.timestamp),
      T_c_w_(T_c_w),
      pyramid_(frame.pyramid),
      colour_(frame.colour),
      small_blurred_(frame.pyramid ? make_small_blurry_image(*frame.pyramid) : cv::Mat()),
      measurements_(std::move(measurements)) {
  FACADESLAM_ASSERT(pyramid_, "a keyframe is made of a frame with its pyramid");
}

}  // namespace facadeslam
