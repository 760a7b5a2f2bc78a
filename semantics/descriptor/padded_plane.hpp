#pragma once
// Planes are stored with a border of reflected pixels (OpenCV's
// BORDER_REFLECT_101: ...2 1 | 0 1 2 ... | n-2 n-3...) as wide as the patch
// radius, so that every keypoint inside the image has a full patch and the
// modules' inner loops never test for the image edge; plus
// PatchView::kReadSlack zeroed columns on the right that the patch kernels
// may read past a patch row (kernel_support.hpp).
#include <opencv2/core.hpp>

namespace facadeslam::semantics {

// A CV_32F matrix of (height + 2 border) x (width + 2 border + slack), the
// slack zeroed. Reuses `plane`'s memory when it already has that shape.
void make_padded_plane(cv::Mat& plane, cv::Size image_size, int border);
cv::Mat make_padded_plane(cv::Size image_size, int border);

// The image-sized part of a padded plane (shares its data); functions
// that write into it fill the plane in place.
cv::Mat plane_interior(const cv::Mat& padded, int border);

// Fills the border (not the slack) from the interior by BORDER_REFLECT_101.
void fill_border_reflect101(cv::Mat& padded, int border);

}  // namespace facadeslam::semantics
