#pragma once
// The map view's legend: a box in the top-left corner listing entries (a
// coloured dot or line and a text), drawn with OpenCV after the read-back,
// scaled with the image height so that it stays readable at any size.
#include <vector>

#include <opencv2/core.hpp>

#include "render/map_view.hpp"

namespace facadeslam::render {

// Draws onto `image` (CV_8UC3). The box is `background_bgr` lightened and
// opaque, so that points under it do not make the text hard to read.
void draw_legend(cv::Mat& image, const std::vector<LegendEntry>& entries, const cv::Scalar& background_bgr);

// Where draw_legend puts its box (for framing and tests).
cv::Rect legend_box(const cv::Size& image_size, const std::vector<LegendEntry>& entries);

}  // namespace facadeslam::render
