#include "semantics/descriptor/gradient_angle_plane.hpp"

#include "semantics/descriptor/kernel_support.hpp"

namespace facadeslam::semantics {
namespace {

// Derivative kernels [-1 0 1] across, smoothed by [edge centre edge] along:
// Sobel (1, 2, 1), Scharr (3, 10, 3). Sobel and Scharr happen to be exact in
// float for 8-bit-derived inputs, so the angles match OpenCV's derivatives.
template <int Edge, int Centre>
FACADESLAM_KERNEL void angles(const cv::Mat& channel, int border, cv::Mat& angle) {
  const float edge = static_cast<float>(Edge), centre = static_cast<float>(Centre);
  for (int y = 0; y < angle.rows; ++y) {
    const float* above = channel.ptr<float>(border + y - 1) + border;
    const float* here = channel.ptr<float>(border + y) + border;
    const float* below = channel.ptr<float>(border + y + 1) + border;
    float* out = angle.ptr<float>(y);
    for (int x = 0; x < angle.cols; ++x) {
      const float gx = edge * (above[x + 1] - above[x - 1]) + centre * (here[x + 1] - here[x - 1]) +
                       edge * (below[x + 1] - below[x - 1]);
      const float gy =
          edge * (below[x - 1] - above[x - 1]) + centre * (below[x] - above[x]) + edge * (below[x + 1] - above[x + 1]);
      out[x] = angle_2pi(gy, gx);
    }
  }
}

}  // namespace

void gradient_angle_plane(const cv::Mat& channel, int border, GradientOperator op, cv::Mat& angle) {
  CV_Assert(border >= 1 && channel.type() == CV_32F && angle.type() == CV_32F);
  if (op == GradientOperator::scharr)
    angles<3, 10>(channel, border, angle);
  else
    angles<1, 2>(channel, border, angle);
}

}  // namespace facadeslam::semantics
