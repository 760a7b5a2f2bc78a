#pragma once
// Preprocessing step 5: the gradient angle of a colour channel at every
// pixel, atan2(gy, gx) in [0, 2pi) with x to the right and y down, from
// 3x3 Sobel or Scharr derivatives (the same kernels as cv::Sobel ksize 3
// and cv::Scharr). The channel's plane must carry a reflected border of at
// least one pixel (BORDER_REFLECT_101, as OpenCV's filters assume).
#include <opencv2/core.hpp>

#include "semantics/descriptor/descriptor_params.hpp"

namespace facadeslam::semantics {

// `channel`: padded plane with `border` >= 1 filled; `angle`: CV_32F of
// the image size (e.g. another plane's interior), written in place.
void gradient_angle_plane(const cv::Mat& channel, int border, GradientOperator op, cv::Mat& angle);

}  // namespace facadeslam::semantics
