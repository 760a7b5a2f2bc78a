#include "semantics/invariance/geometric_transforms.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include <opencv2/imgproc.hpp>

#include "core/util/angles.hpp"
#include "core/util/error.hpp"
#include "semantics/invariance/transform_input.hpp"
#include "semantics/text.hpp"

namespace facadeslam::semantics {
namespace {

struct Tilt {
  double viewpoint_degrees;  // theta
  double direction_degrees;  // phi
};

// Cases 1..10 (header comment).
constexpr std::array<Tilt, kAffineCaseCount> kTilts{{
    {20, 0},
    {30, 0},
    {40, 0},
    {50, 0},
    {60, 0},
    {20, 45},
    {30, 45},
    {40, 45},
    {50, 45},
    {60, 45},
}};

const Tilt& tilt_of(int affine_case) {
  if (affine_case < 1 || affine_case > kAffineCaseCount)
    throw Error(
        cat("affine case ", affine_case, " does not exist (expected 0 = identity or 1..", kAffineCaseCount, ")"));
  return kTilts[static_cast<std::size_t>(affine_case - 1)];
}

}  // namespace

cv::Matx22d affine_case_matrix(int affine_case) {
  if (affine_case == 0) return cv::Matx22d::eye();
  const Tilt& t = tilt_of(affine_case);
  const double shrink = 1.0 - std::cos(deg_to_rad(t.viewpoint_degrees));
  const double c = std::cos(deg_to_rad(t.direction_degrees)), s = std::sin(deg_to_rad(t.direction_degrees));
  return cv::Matx22d(1.0 - shrink * c * c, -shrink * c * s, -shrink * c * s, 1.0 - shrink * s * s);
}

std::string affine_case_description(int affine_case) {
  if (affine_case == 0) return "identity";
  const Tilt& t = tilt_of(affine_case);
  return cat("tilt ", static_cast<int>(t.viewpoint_degrees), " deg along ", static_cast<int>(t.direction_degrees),
             " deg");
}

TransformedImage warp_about_centre(const cv::Mat& bgr, const cv::Matx22d& a) {
  require_colour_image(bgr);
  // The image covers [-0.5, size - 0.5] in pixel-centre coordinates.
  const cv::Point2d centre((bgr.cols - 1) / 2.0, (bgr.rows - 1) / 2.0);
  double x_lo = HUGE_VAL, x_hi = -HUGE_VAL, y_lo = HUGE_VAL, y_hi = -HUGE_VAL;
  for (const double cx : {-0.5, bgr.cols - 0.5})
    for (const double cy : {-0.5, bgr.rows - 0.5}) {
      const cv::Vec2d q = a * cv::Vec2d(cx - centre.x, cy - centre.y);
      x_lo = std::min(x_lo, q[0]);
      x_hi = std::max(x_hi, q[0]);
      y_lo = std::min(y_lo, q[1]);
      y_hi = std::max(y_hi, q[1]);
    }
  // The tolerance keeps exact sizes exact (the identity keeps its size).
  const int width = std::max(1, static_cast<int>(std::ceil(x_hi - x_lo - 1e-6)));
  const int height = std::max(1, static_cast<int>(std::ceil(y_hi - y_lo - 1e-6)));
  const cv::Point2d new_centre((width - 1) / 2.0, (height - 1) / 2.0);
  const cv::Vec2d shifted_centre = a * cv::Vec2d(centre.x, centre.y);

  TransformedImage out;
  out.point_map = cv::Matx23d(a(0, 0), a(0, 1), new_centre.x - shifted_centre[0],  //
                              a(1, 0), a(1, 1), new_centre.y - shifted_centre[1]);
  const cv::Size size(width, height);
  cv::warpAffine(bgr, out.bgr, out.point_map, size, cv::INTER_LINEAR, cv::BORDER_CONSTANT, cv::Scalar::all(0));
  const cv::Mat all_valid(bgr.size(), CV_8U, cv::Scalar(255));
  cv::warpAffine(all_valid, out.valid, out.point_map, size, cv::INTER_NEAREST, cv::BORDER_CONSTANT, cv::Scalar(0));
  return out;
}

TransformedImage rotate_image(const cv::Mat& bgr, double degrees) {
  if (!std::isfinite(degrees)) throw Error("rotation: the angle must be a finite number of degrees");
  const double c = std::cos(deg_to_rad(degrees)), s = std::sin(deg_to_rad(degrees));
  // y points down, so this turns the picture counter-clockwise as seen.
  return warp_about_centre(bgr, cv::Matx22d(c, s, -s, c));
}

TransformedImage resize_image(const cv::Mat& bgr, double factor) {
  require_colour_image(bgr);
  if (!(factor > 0.0) || !std::isfinite(factor)) throw Error("resize: the factor must be a positive number");
  const cv::Size size(std::max(1, static_cast<int>(std::lround(bgr.cols * factor))),
                      std::max(1, static_cast<int>(std::lround(bgr.rows * factor))));
  cv::Mat resized;
  cv::resize(bgr, resized, size, 0, 0, factor < 1.0 ? cv::INTER_AREA : cv::INTER_LINEAR);
  TransformedImage out = same_geometry(std::move(resized));
  // cv::resize aligns pixel edges, not centres: x' + 0.5 = s (x + 0.5).
  const double sx = static_cast<double>(size.width) / bgr.cols, sy = static_cast<double>(size.height) / bgr.rows;
  out.point_map = cv::Matx23d(sx, 0, 0.5 * sx - 0.5, 0, sy, 0.5 * sy - 0.5);
  return out;
}

TransformedImage affine_image(const cv::Mat& bgr, int affine_case) {
  return warp_about_centre(bgr, affine_case_matrix(affine_case));
}

}  // namespace facadeslam::semantics
