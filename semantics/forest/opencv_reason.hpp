#pragma once
// The part of an OpenCV exception worth showing a user: OpenCV's own
// reason (e.err) without its file/line banner, or what() when it has none.
#include <string>

#include <opencv2/core.hpp>

namespace facadeslam::semantics {

inline std::string opencv_reason(const cv::Exception& e) { return e.err.empty() ? std::string(e.what()) : e.err; }

}  // namespace facadeslam::semantics
