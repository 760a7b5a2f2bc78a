#include "core/map/keyframe.hpp"

namespace facadeslam {

KeyFrame::KeyFrame(Id id, double timestamp, const SE3d& T_c_w, std::shared_ptr<const ImagePyramid> pyramid,
                   cv::Mat colour, cv::Mat small_blurred)
    : id_(id),
      timestamp_(timestamp),
      T_c_w_(T_c_w),
      pyramid_(std::move(pyramid)),
      colour_(std::move(colour)),
      small_blurred_(std::move(small_blurred)) {}

}  // namespace facadeslam
