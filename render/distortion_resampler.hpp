#pragma once
// Rendering through a distorted camera. OpenGL rasterises straight lines
// only, so a camera with lens distortion is rendered in two steps:
//   1. an ideal pinhole "virtual" camera with the same focal lengths and a
//      field of view just large enough to hold every ray of the real camera;
//   2. a post-pass: for each output pixel, the ray the real camera sees there
//      (Camera::unproject) is projected into the virtual image, which is
//      sampled bicubically for colour and at the nearest pixel for labels and
//      depth (labels must stay class ids; z-depth belongs to the surface point
//      and does not change between the two cameras, which share the pose).
// A camera without distortion needs neither step (needs_resampling()).
#include <opencv2/core.hpp>

#include "core/camera/camera.hpp"
#include "render/projection.hpp"

namespace facadeslam::render {

// True for a pinhole camera with non-zero coefficients or an ATAN camera
// with w != 0.
bool needs_resampling(const Camera& camera);

// The camera's linear part (fx, fy, cx, cy, size), for undistorted cameras.
PinholeIntrinsics pinhole_intrinsics(const Camera& camera);

class DistortionResampler {
 public:
  // Builds the virtual camera and the per-pixel lookup. The virtual image
  // keeps `margin` (>= 2, for the bicubic kernel) pixels around the
  // outermost sample. If holding every ray
  // at the real focal length would need more than `max_size` pixels across,
  // the virtual focal length is reduced to fit (the centre then loses some
  // detail); Error if the camera's field reaches 90 degrees.
  explicit DistortionResampler(const Camera& camera, int margin = 2, int max_size = 4096);

  const PinholeIntrinsics& virtual_camera() const { return virtual_; }
  int width() const { return map_.cols; }
  int height() const { return map_.rows; }
  // Where output pixel (x, y) samples the virtual image (our pixel convention).
  cv::Vec2d source(int x, int y) const { return map_.at<cv::Vec2d>(y, x); }

  // Bilinear resampling of a CV_32FC(n) image rendered by virtual_camera().
  cv::Mat resample_linear(const cv::Mat& virtual_image) const;
  // Bicubic (Catmull-Rom) resampling: sharper than bilinear, and without its
  // position-dependent smoothing, which would shift edges by a few
  // hundredths of a pixel (requires margin >= 2).
  cv::Mat resample_cubic(const cv::Mat& virtual_image) const;
  // Nearest-pixel resampling of an image of any type rendered by
  // virtual_camera().
  cv::Mat resample_nearest(const cv::Mat& virtual_image) const;

 private:
  PinholeIntrinsics virtual_;
  cv::Mat map_;  // CV_64FC2: virtual-image coordinates per output pixel
};

}  // namespace facadeslam::render
