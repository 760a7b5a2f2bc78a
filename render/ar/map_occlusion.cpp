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

cv::Mat occluder_depth(const std::vector<OccluderPoint>& points, const Eigen::Isometry3d& T_c_w,
                       const PinholeIntrinsics& intrinsics, double spacing, const OcclusionOptions& options) {
  cv::Mat sparse(intrinsics.height, intrinsics.width, CV_32FC1, cv::Scalar(kNothing));
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
    if (px.x() < -radius || px.y() < -radius || px.x() > intrinsics.width + radius ||
        px.y() > intrinsics.height + radius)
      continue;
    splat(is_surface ? surface : sparse, px.x(), px.y(), radius, static_cast<float>(p_c.z()));
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
  return cv::min(sparse, surface);
}

}  // namespace facadeslam::render::ar
