#pragma once
// The one input check every image transform of the invariance suite makes.
#include <opencv2/core.hpp>

#include "core/util/error.hpp"

namespace facadeslam::semantics {

inline void require_colour_image(const cv::Mat& bgr) {
  if (bgr.empty() || bgr.type() != CV_8UC3) throw Error("image transform: expected a non-empty 8-bit BGR image");
}

}  // namespace facadeslam::semantics
