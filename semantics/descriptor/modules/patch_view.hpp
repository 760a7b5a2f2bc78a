#pragma once
// A square (2r+1) x (2r+1) float patch inside a larger plane, addressed by
// row pointers; modules read their keypoint's patch through it.
#include <cstddef>

#include <opencv2/core.hpp>

namespace facadeslam::semantics {

struct PatchView {
  // Kernels may read up to this many floats past the end of each patch row
  // (kernel_support.hpp); every plane provides them.
  static constexpr int kReadSlack = 8;

  const float* data = nullptr;  // top-left pixel of the patch
  std::ptrdiff_t stride = 0;    // floats between rows
  int radius = 0;

  int size() const { return 2 * radius + 1; }
  const float* row(int i) const { return data + i * stride; }
  // Offsets from the centre pixel: dx to the right, dy down.
  float at(int dx, int dy) const { return data[(radius + dy) * stride + radius + dx]; }
};

// Owns a copy of a square, odd-sized CV_32F matrix with the read slack, for
// tests and tools: `f(PatchBuffer(m))` passes a valid view for the call.
class PatchBuffer {
 public:
  explicit PatchBuffer(const cv::Mat& square) {
    CV_Assert(square.type() == CV_32F && square.rows == square.cols && square.rows % 2 == 1);
    storage_ = cv::Mat::zeros(square.rows, square.cols + PatchView::kReadSlack, CV_32F);
    square.copyTo(storage_(cv::Rect(0, 0, square.cols, square.rows)));
  }
  PatchView view() const {
    return {storage_.ptr<float>(0), static_cast<std::ptrdiff_t>(storage_.step1()), storage_.rows / 2};
  }
  operator PatchView() const { return view(); }  // NOLINT: a buffer is used as its view

 private:
  cv::Mat storage_;
};

inline PatchBuffer view_of(const cv::Mat& square) { return PatchBuffer(square); }

}  // namespace facadeslam::semantics
