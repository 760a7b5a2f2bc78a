#include "render/distortion_resampler.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <type_traits>

#include "core/util/error.hpp"

namespace facadeslam::render {

bool needs_resampling(const Camera& camera) {
  return camera.visit([](const auto& m) {
    using M = std::decay_t<decltype(m)>;
    if constexpr (std::is_same_v<M, PinholeRadTan>)
      return m.has_distortion();
    else
      return m.w != 0.0;
  });
}

PinholeIntrinsics pinhole_intrinsics(const Camera& camera) {
  return {camera.width(), camera.height(), camera.fx(), camera.fy(), camera.cx(), camera.cy()};
}

DistortionResampler::DistortionResampler(const Camera& camera, int margin, int max_size) {
  if (margin < 2) throw Error("render: the resampling margin must be at least 2 pixels (bicubic kernel)");
  const int w = camera.width(), h = camera.height();
  // Undistorted normalised coordinates of every pixel centre.
  cv::Mat rays(h, w, CV_64FC2);
  double min_x = std::numeric_limits<double>::infinity(), max_x = -min_x;
  double min_y = min_x, max_y = -min_x;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Eigen::Vector3d ray = camera.unproject(Eigen::Vector2d(x, y));
      if (!std::isfinite(ray.x()) || !std::isfinite(ray.y()) || ray.z() <= 0.0)
        throw Error("render: the camera's field of view reaches 90 degrees; it cannot be rendered through a pinhole");
      rays.at<cv::Vec2d>(y, x) = {ray.x() / ray.z(), ray.y() / ray.z()};
      min_x = std::min(min_x, ray.x() / ray.z());
      max_x = std::max(max_x, ray.x() / ray.z());
      min_y = std::min(min_y, ray.y() / ray.z());
      max_y = std::max(max_y, ray.y() / ray.z());
    }
  // Same focal lengths as the real camera, unless that needs more than
  // max_size pixels across.
  // The image is the span plus the margins plus up to two pixels of rounding.
  const double room = max_size - 2.0 * margin - 2.0;
  if (room <= 0.0) throw Error("render: the virtual camera's size limit leaves no room inside its margins");
  const double scale = std::min({1.0, room / (camera.fx() * (max_x - min_x)), room / (camera.fy() * (max_y - min_y))});
  virtual_.fx = camera.fx() * scale;
  virtual_.fy = camera.fy() * scale;
  virtual_.cx = margin - virtual_.fx * min_x;
  virtual_.cy = margin - virtual_.fy * min_y;
  virtual_.width = static_cast<int>(std::ceil(virtual_.cx + virtual_.fx * max_x + margin)) + 1;
  virtual_.height = static_cast<int>(std::ceil(virtual_.cy + virtual_.fy * max_y + margin)) + 1;

  map_.create(h, w, CV_64FC2);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const cv::Vec2d r = rays.at<cv::Vec2d>(y, x);
      map_.at<cv::Vec2d>(y, x) = {virtual_.fx * r[0] + virtual_.cx, virtual_.fy * r[1] + virtual_.cy};
    }
}

namespace {

// Catmull-Rom weights (Keys' cubic convolution, a = -1/2) of the four samples
// at offsets -1, 0, 1, 2 for a fractional position t in [0, 1).
void cubic_weights(float t, float w[4]) {
  const float t2 = t * t, t3 = t2 * t;
  w[0] = -0.5f * t3 + t2 - 0.5f * t;
  w[1] = 1.5f * t3 - 2.5f * t2 + 1.f;
  w[2] = -1.5f * t3 + 2.f * t2 + 0.5f * t;
  w[3] = 0.5f * t3 - 0.5f * t2;
}

}  // namespace

cv::Mat DistortionResampler::resample_linear(const cv::Mat& src) const {
  if (src.depth() != CV_32F || src.cols != virtual_.width || src.rows != virtual_.height)
    throw Error("render: resample_linear expects a CV_32F image of the virtual camera's size");
  const int channels = src.channels();
  cv::Mat out(map_.rows, map_.cols, src.type());
  for (int y = 0; y < map_.rows; ++y) {
    float* dst = out.ptr<float>(y);
    for (int x = 0; x < map_.cols; ++x) {
      const cv::Vec2d p = map_.at<cv::Vec2d>(y, x);
      // The margin keeps (x0, y0) and (x0 + 1, y0 + 1) inside the image.
      const int x0 = static_cast<int>(std::floor(p[0])), y0 = static_cast<int>(std::floor(p[1]));
      const float ax = static_cast<float>(p[0] - x0), ay = static_cast<float>(p[1] - y0);
      const float* r0 = src.ptr<float>(y0) + x0 * channels;
      const float* r1 = src.ptr<float>(y0 + 1) + x0 * channels;
      for (int c = 0; c < channels; ++c) {
        const float top = r0[c] + ax * (r0[c + channels] - r0[c]);
        const float bottom = r1[c] + ax * (r1[c + channels] - r1[c]);
        dst[x * channels + c] = top + ay * (bottom - top);
      }
    }
  }
  return out;
}

cv::Mat DistortionResampler::resample_cubic(const cv::Mat& src) const {
  if (src.depth() != CV_32F || src.cols != virtual_.width || src.rows != virtual_.height)
    throw Error("render: resample_cubic expects a CV_32F image of the virtual camera's size");
  const int channels = src.channels();
  cv::Mat out(map_.rows, map_.cols, src.type());
  for (int y = 0; y < map_.rows; ++y) {
    float* dst = out.ptr<float>(y);
    for (int x = 0; x < map_.cols; ++x) {
      const cv::Vec2d p = map_.at<cv::Vec2d>(y, x);
      // The margin (>= 2) keeps rows y0 - 1 .. y0 + 2 and columns x0 - 1 ..
      // x0 + 2 inside the image.
      const int x0 = static_cast<int>(std::floor(p[0])), y0 = static_cast<int>(std::floor(p[1]));
      float wx[4], wy[4];
      cubic_weights(static_cast<float>(p[0] - x0), wx);
      cubic_weights(static_cast<float>(p[1] - y0), wy);
      for (int c = 0; c < channels; ++c) {
        float sum = 0.f;
        for (int j = 0; j < 4; ++j) {
          const float* row = src.ptr<float>(y0 - 1 + j) + (x0 - 1) * channels + c;
          sum +=
              wy[j] * (wx[0] * row[0] + wx[1] * row[channels] + wx[2] * row[2 * channels] + wx[3] * row[3 * channels]);
        }
        dst[x * channels + c] = sum;
      }
    }
  }
  return out;
}

cv::Mat DistortionResampler::resample_nearest(const cv::Mat& src) const {
  if (src.cols != virtual_.width || src.rows != virtual_.height)
    throw Error("render: resample_nearest expects an image of the virtual camera's size");
  const std::size_t bytes = src.elemSize();
  cv::Mat out(map_.rows, map_.cols, src.type());
  for (int y = 0; y < map_.rows; ++y)
    for (int x = 0; x < map_.cols; ++x) {
      const cv::Vec2d p = map_.at<cv::Vec2d>(y, x);
      const int sx = static_cast<int>(std::floor(p[0] + 0.5)), sy = static_cast<int>(std::floor(p[1] + 0.5));
      std::memcpy(out.ptr(y, x), src.ptr(sy, sx), bytes);
    }
  return out;
}

}  // namespace facadeslam::render
