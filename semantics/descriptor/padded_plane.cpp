#include "semantics/descriptor/padded_plane.hpp"

#include <cstring>

#include "semantics/descriptor/modules/patch_view.hpp"

namespace facadeslam::semantics {
namespace {
constexpr int kSlack = PatchView::kReadSlack;
}

void make_padded_plane(cv::Mat& plane, cv::Size image_size, int border) {
  const int rows = image_size.height + 2 * border, cols = image_size.width + 2 * border + kSlack;
  // create() keeps the memory exactly when the shape and type are unchanged,
  // and nothing writes the slack but this: zero it only for new memory.
  const bool kept = !plane.empty() && plane.rows == rows && plane.cols == cols && plane.type() == CV_32F;
  plane.create(rows, cols, CV_32F);
  if (!kept) plane.colRange(plane.cols - kSlack, plane.cols).setTo(0.0f);
}

cv::Mat make_padded_plane(cv::Size image_size, int border) {
  cv::Mat plane;
  make_padded_plane(plane, image_size, border);
  return plane;
}

cv::Mat plane_interior(const cv::Mat& padded, int border) {
  return padded(cv::Rect(border, border, padded.cols - 2 * border - kSlack, padded.rows - 2 * border));
}

void fill_border_reflect101(cv::Mat& padded, int border) {
  if (border == 0) return;
  const int width = padded.cols - 2 * border - kSlack;
  const int height = padded.rows - 2 * border;
  // Source columns of the left and right border, computed once.
  int left[64], right[64];
  CV_Assert(border <= 64);
  for (int i = 0; i < border; ++i) {
    left[i] = border + cv::borderInterpolate(i - border, width, cv::BORDER_REFLECT_101);
    right[i] = border + cv::borderInterpolate(width + i, width, cv::BORDER_REFLECT_101);
  }
  for (int y = border; y < border + height; ++y) {
    float* row = padded.ptr<float>(y);
    for (int i = 0; i < border; ++i) {
      row[i] = row[left[i]];
      row[border + width + i] = row[right[i]];
    }
  }
  const std::size_t row_bytes = static_cast<std::size_t>(padded.cols) * sizeof(float);
  for (int i = 0; i < border; ++i) {
    std::memcpy(padded.ptr<float>(i),
                padded.ptr<float>(border + cv::borderInterpolate(i - border, height, cv::BORDER_REFLECT_101)),
                row_bytes);
    std::memcpy(padded.ptr<float>(border + height + i),
                padded.ptr<float>(border + cv::borderInterpolate(height + i, height, cv::BORDER_REFLECT_101)),
                row_bytes);
  }
}

}  // namespace facadeslam::semantics
