#pragma once
// Preprocessing step 4a: Canny edges of the grey blurred image, exactly as
// cv::Canny(grey, edges, low, high, aperture, L1 norm) computes them: the
// Sobel derivatives (3x3 or 5x5, 16-bit, replicated border, as cv::Canny
// uses internally), the L1 magnitude, non-maximum suppression with OpenCV's
// fixed-point direction tests and tie rules, and hysteresis. Written here
// with vectorised integer code: OpenCV's generic 5x5 16-bit Sobel and its
// branchy suppression took 5 ms of a 640 x 480 facade photo on one core.
#include <vector>

#include <opencv2/core.hpp>

namespace facadeslam::semantics {

struct CannyBuffers {
  cv::Mat padded, smooth, derivative, dx, dy, magnitude, map;
  std::vector<uchar*> stack, row_seeds;
};

// `grey`: CV_8U. `edges`: CV_8U, 255 on edges. aperture 3 or 5.
void canny_edges(const cv::Mat& grey, int aperture, double low, double high, cv::Mat& edges, CannyBuffers& buffers);

}  // namespace facadeslam::semantics
