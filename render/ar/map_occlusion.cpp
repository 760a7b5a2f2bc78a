#include "render/ar/map_occlusion.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <opencv2/imgproc.hpp>

namespace facadeslam::render::ar {
namespace {

constexpr float kNothing = std::numeric_limits<float>::infinity();

// A disc of depth z (the nearer depth wins) centred on (u, v).
void splat(cv::Mat& depth, double u, double v, double radius, float z) {
  const int x0 = std::max(0, static_cast<int>(std::floor(u - radius)));
  const int x1 = std::min(depth.cols - 1, static_cast<int>(std::ceil(u + radius)));
  const int y0 = std::max(0, static_cast<int>(std::floor(v - radius)));
  const int y1 = std::min(depth.rows - 1, static_cast<int>(std::ceil(v + radius)));
  const double r2 = radius * radius;
  for (int y = y0; y <= y1; ++y) {
    float* row = depth.ptr<float>(y);
    const double dy = y - v;
    for (int x = x0; x <= x1; ++x) {
      const double dx = x - u;
      if (dx * dx + dy * dy <= r2) row[x] = std::min(row[x], z);
    }
  }
}

}  // namespace

double point_spacing(const std::vector<OccluderPoint>& points) {
  if (points.size() < 2) return 0.0;
  const std::size_t step = std::max<std::size_t>(1, points.size() / 400);
  std::vector<double> nearest;
  for (std::size_t i = 0; i < points.size(); i += step) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < points.size(); ++j)
      if (j != i) best = std::min(best, (points[i].p_w - points[j].p_w).squaredNorm());
    nearest.push_back(std::sqrt(best));
  }
  auto middle = nearest.begin() + static_cast<std::ptrdiff_t>(nearest.size() / 2);
  std::nth_element(nearest.begin(), middle, nearest.end());
  return *middle;
}

cv::Rect object_region(const VirtualObject& object, const Eigen::Isometry3d& T_c_w,
                       const PinholeIntrinsics& intrinsics) {
  const cv::Rect image(0, 0, intrinsics.width, intrinsics.height);
  double u0 = 1e300, v0 = 1e300, u1 = -1e300, v1 = -1e300;
  for (const Eigen::Vector3d& corner : object.corners_w()) {
    const Eigen::Vector3d p_c = T_c_w * corner;
    if (p_c.z() <= 1e-9) return image;
    const Eigen::Vector2d px = intrinsics.project(p_c);
    u0 = std::min(u0, px.x()), v0 = std::min(v0, px.y()), u1 = std::max(u1, px.x()), v1 = std::max(v1, px.y());
  }
  // Two pixels beyond the corners: the soft edge samples the neighbours.
  const double x0 = std::clamp(std::floor(u0) - 2.0, 0.0, static_cast<double>(intrinsics.width));
  const double y0 = std::clamp(std::floor(v0) - 2.0, 0.0, static_cast<double>(intrinsics.height));
  const double x1 = std::clamp(std::ceil(u1) + 3.0, 0.0, static_cast<double>(intrinsics.width));
  const double y1 = std::clamp(std::ceil(v1) + 3.0, 0.0, static_cast<double>(intrinsics.height));
  return cv::Rect(static_cast<int>(x0), static_cast<int>(y0), static_cast<int>(x1 - x0), static_cast<int>(y1 - y0)) &
         image;
}

cv::Mat occluder_depth(const std::vector<OccluderPoint>& points, const Eigen::Isometry3d& T_c_w,
                       const PinholeIntrinsics& intrinsics, double spacing, const OcclusionOptions& options,
                       std::optional<cv::Rect> wanted) {
  const cv::Rect image(0, 0, intrinsics.width, intrinsics.height);
  const cv::Rect region = wanted ? *wanted & image : image;
  cv::Mat depth(intrinsics.height, intrinsics.width, CV_32FC1, cv::Scalar(kNothing));
  if (region.empty()) return depth;
  // Drawn in the region grown by the closing's reach (so that it closes the
  // same gaps as over the whole image), then cut back to the region.
  const int reach = std::max(0, options.surface_close_px);
  const cv::Rect drawn =
      cv::Rect(region.x - reach, region.y - reach, region.width + 2 * reach, region.height + 2 * reach) & image;
  cv::Mat sparse(drawn.size(), CV_32FC1, cv::Scalar(kNothing));
  cv::Mat surface = sparse.clone();
  bool any_surface = false;
  for (const OccluderPoint& point : points) {
    if (point.kind == OccluderKind::none) continue;
    const Eigen::Vector3d p_c = T_c_w * point.p_w;
    if (p_c.z() <= 1e-9) continue;
    const Eigen::Vector2d px = intrinsics.project(p_c);
    const bool is_surface = point.kind == OccluderKind::surface;
    const double share = is_surface ? options.surface_radius : options.sparse_radius;
    const double radius = std::clamp(share * spacing * intrinsics.fx / p_c.z(), 0.5, options.max_radius_px);
    const double u = px.x() - drawn.x, v = px.y() - drawn.y;
    if (u < -radius || v < -radius || u > drawn.width + radius || v > drawn.height + radius) continue;
    splat(is_surface ? surface : sparse, u, v, radius, static_cast<float>(p_c.z()));
    any_surface = any_surface || is_surface;
  }
  if (any_surface && options.surface_close_px > 1) {
    // Closing on depth: a dilation (the nearer of the neighbours: erode on z)
    // then the reverse fills the gaps between a facade's splats without
    // growing its outline.
    const cv::Mat kernel =
        cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(options.surface_close_px, options.surface_close_px));
    cv::Mat grown;
    cv::erode(surface, grown, kernel, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(kNothing));
    cv::dilate(grown, surface, kernel, cv::Point(-1, -1), 1, cv::BORDER_CONSTANT, cv::Scalar(kNothing));
  }
  const cv::Rect inside(region.x - drawn.x, region.y - drawn.y, region.width, region.height);
  cv::Mat out = depth(region);
  cv::min(sparse(inside), surface(inside), out);
  return depth;
}

}  // namespace facadeslam::render::ar
