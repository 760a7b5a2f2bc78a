#pragma once
// Preprocessing step 4a: Canny edges of the grey blurred image, exactly as
// cv::Canny(grey, edges, low, high, aperture, L1 norm) computes them. The
// Sobel derivatives (3x3 or 5x5, 16-bit, replicated border, as cv::Canny
// uses internally) are computed here with vectorised integer code and
// handed to cv::Canny's derivative overload: OpenCV's generic 5x5 16-bit
// Sobel costs more than the rest of Canny on facade images.
#include <opencv2/core.hpp>

namespace facadeslam::semantics {

struct CannyBuffers {
  cv::Mat padded, smooth, derivative, dx, dy;
};

// `grey`: CV_8U. `edges`: CV_8U, 255 on edges. aperture 3 or 5.
void canny_edges(const cv::Mat& grey, int aperture, double low, double high, cv::Mat& edges, CannyBuffers& buffers);

}  // namespace facadeslam::semantics
