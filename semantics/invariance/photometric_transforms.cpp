#include "semantics/invariance/photometric_transforms.hpp"

#include <cmath>
#include <vector>

#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/util/error.hpp"
#include "semantics/invariance/illuminant.hpp"
#include "semantics/invariance/transform_input.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {

cv::Mat blur_image(const cv::Mat& bgr, int kernel) {
  require_colour_image(bgr);
  if (kernel < 1 || kernel % 2 == 0) throw Error(cat("blur: the kernel size must be odd and >= 1, got ", kernel));
  cv::Mat out;
  cv::GaussianBlur(bgr, out, cv::Size(kernel, kernel), 0.0, 0.0, cv::BORDER_REFLECT_101);
  return out;
}

cv::Mat scale_intensity(const cv::Mat& bgr, double factor) {
  require_colour_image(bgr);
  if (!(factor > 0.0) || !std::isfinite(factor)) throw Error("intensity scale: the factor must be a positive number");
  cv::Mat out;
  bgr.convertTo(out, CV_8UC3, factor, 0.0);
  return out;
}

cv::Mat shift_intensity(const cv::Mat& bgr, double offset) {
  require_colour_image(bgr);
  if (!std::isfinite(offset)) throw Error("intensity shift: the offset must be a finite number");
  cv::Mat out;
  bgr.convertTo(out, CV_8UC3, 1.0, offset);
  return out;
}

cv::Mat change_illuminant(const cv::Mat& bgr, double kelvin) {
  require_colour_image(bgr);
  const cv::Vec3d g = illuminant_gains_bgr(kelvin);
  const cv::Matx33d diagonal(g[0], 0, 0, 0, g[1], 0, 0, 0, g[2]);
  cv::Mat out;
  cv::transform(bgr, out, diagonal);  // saturates to 0..255
  return out;
}

cv::Mat jpeg_round_trip(const cv::Mat& bgr, int quality) {
  require_colour_image(bgr);
  if (quality < 0 || quality > 100) throw Error(cat("jpeg: the quality must be 0..100, got ", quality));
  std::vector<uchar> encoded;
  if (!cv::imencode(".jpg", bgr, encoded, {cv::IMWRITE_JPEG_QUALITY, quality}))
    throw Error("jpeg: OpenCV could not encode the image");
  cv::Mat out = cv::imdecode(encoded, cv::IMREAD_COLOR);
  if (out.empty()) throw Error("jpeg: OpenCV could not decode its own JPEG");
  return out;
}

}  // namespace facadeslam::semantics
