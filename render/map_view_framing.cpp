#include "render/map_view_framing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Eigenvalues>

#include "core/util/angles.hpp"
#include "core/util/error.hpp"

namespace facadeslam::render {
// Named, so that the unity build's other render files cannot clash with these.
namespace map_view_framing_detail {
namespace {

// Component of v orthogonal to the unit vector n, normalised; zero if v is
// (nearly) parallel to n.
Eigen::Vector3d orthogonal_unit(const Eigen::Vector3d& v, const Eigen::Vector3d& n) {
  const Eigen::Vector3d o = v - v.dot(n) * n;
  return o.norm() > 1e-6 ? Eigen::Vector3d(o.normalized()) : Eigen::Vector3d::Zero();
}

double percentile(std::vector<double> values, double percent) {
  const auto rank =
      static_cast<std::size_t>(std::clamp(std::round(percent / 100.0 * static_cast<double>(values.size() - 1)), 0.0,
                                          static_cast<double>(values.size() - 1)));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(rank), values.end());
  return values[rank];
}

// The points inside the low-high percentile box along (right, forward, up),
// plus the anchors, and their bounding box in that frame.
struct RobustBox {
  Eigen::Matrix3d R_box_w;  // rows: right, forward, up
  std::vector<Eigen::Vector3d> framed;
  Eigen::Vector3d lo, hi;
};

RobustBox robust_box(const std::vector<Eigen::Vector3f>& points_w, const std::vector<Eigen::Vector3d>& anchors_w,
                     const ViewAxes& axes, const FramingOptions& options) {
  RobustBox box;
  box.R_box_w.row(0) = axes.forward_w.cross(axes.up_w).transpose();
  box.R_box_w.row(1) = axes.forward_w.transpose();
  box.R_box_w.row(2) = axes.up_w.transpose();
  if (!points_w.empty()) {
    Eigen::Vector3d p_lo, p_hi;
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> values;
      values.reserve(points_w.size());
      for (const Eigen::Vector3f& p : points_w) values.push_back(box.R_box_w.row(axis).dot(p.cast<double>()));
      p_lo[axis] = percentile(values, options.low_percentile);
      p_hi[axis] = percentile(std::move(values), options.high_percentile);
    }
    for (const Eigen::Vector3f& p : points_w) {
      const Eigen::Vector3d b = box.R_box_w * p.cast<double>();
      if ((b.array() >= p_lo.array()).all() && (b.array() <= p_hi.array()).all())
        box.framed.push_back(p.cast<double>());
    }
  }
  box.framed.insert(box.framed.end(), anchors_w.begin(), anchors_w.end());
  if (box.framed.empty()) box.framed.push_back(Eigen::Vector3d::Zero());
  box.lo = Eigen::Vector3d::Constant(std::numeric_limits<double>::infinity());
  box.hi = -box.lo;
  for (const Eigen::Vector3d& p : box.framed) {
    box.lo = box.lo.cwiseMin(box.R_box_w * p);
    box.hi = box.hi.cwiseMax(box.R_box_w * p);
  }
  return box;
}

// The horizontal direction across the points' main horizontal axis (their
// largest principal component in the plane normal to up), or along it, on
// the side of axes.forward_w (ties: either).
Eigen::Vector3d across_major_axis(const std::vector<Eigen::Vector3d>& points_w, const ViewAxes& axes, bool along) {
  const Eigen::Vector3d right = axes.forward_w.cross(axes.up_w);
  Eigen::Vector2d mean = Eigen::Vector2d::Zero();
  for (const Eigen::Vector3d& p : points_w) mean += Eigen::Vector2d(p.dot(right), p.dot(axes.forward_w));
  mean /= static_cast<double>(points_w.size());
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  for (const Eigen::Vector3d& p : points_w) {
    const Eigen::Vector2d d = Eigen::Vector2d(p.dot(right), p.dot(axes.forward_w)) - mean;
    covariance += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> solver(covariance);
  const Eigen::Vector2d major = solver.eigenvectors().col(1);  // eigenvalues ascend
  const Eigen::Vector3d major_w = (major.x() * right + major.y() * axes.forward_w).normalized();
  const Eigen::Vector3d across = along ? major_w : axes.up_w.cross(major_w).normalized();
  return across.dot(axes.forward_w) >= 0 ? across : Eigen::Vector3d(-across);
}

// Rows of R_c_w: the virtual camera's x (right), y (down), z (optical axis) in the world.
Eigen::Matrix3d view_rotation(const ViewAxes& axes, MapViewKind kind, double elevation_deg) {
  const Eigen::Vector3d& u = axes.up_w;
  const Eigen::Vector3d& f = axes.forward_w;
  Eigen::Vector3d y, z;
  if (kind == MapViewKind::top) {
    z = -u;
    y = -f;
  } else {
    const double e = deg_to_rad(elevation_deg);
    z = std::cos(e) * f - std::sin(e) * u;
    y = -(std::sin(e) * f + std::cos(e) * u);
  }
  Eigen::Matrix3d R_c_w;
  R_c_w.row(0) = y.cross(z).transpose();
  R_c_w.row(1) = y.transpose();
  R_c_w.row(2) = z.transpose();
  return R_c_w;
}

}  // namespace
}  // namespace map_view_framing_detail

ViewAxes view_axes_from_cameras(const std::vector<Eigen::Isometry3d>& keyframes_T_c_w) {
  using map_view_framing_detail::orthogonal_unit;
  ViewAxes axes;
  if (keyframes_T_c_w.empty()) return axes;
  Eigen::Vector3d up = Eigen::Vector3d::Zero(), forward = Eigen::Vector3d::Zero();
  for (const Eigen::Isometry3d& T_c_w : keyframes_T_c_w) {
    // Row i of R_c_w is the camera's axis i in the world.
    up -= T_c_w.linear().row(1).transpose();
    forward += T_c_w.linear().row(2).transpose();
  }
  if (up.norm() < 1e-6) up = -keyframes_T_c_w.front().linear().row(1).transpose();
  axes.up_w = up.normalized();
  axes.forward_w = orthogonal_unit(forward, axes.up_w);
  // Cameras that looked every way around: the first one's view.
  if (axes.forward_w.isZero())
    axes.forward_w = orthogonal_unit(keyframes_T_c_w.front().linear().row(2).transpose(), axes.up_w);
  // A first camera looking straight up or down: any horizontal direction.
  if (axes.forward_w.isZero()) axes.forward_w = orthogonal_unit(Eigen::Vector3d::UnitX(), axes.up_w);
  if (axes.forward_w.isZero()) axes.forward_w = orthogonal_unit(Eigen::Vector3d::UnitZ(), axes.up_w);
  return axes;
}

MapViewFraming frame_map_view(const std::vector<Eigen::Vector3f>& points_w,
                              const std::vector<Eigen::Vector3d>& anchors_w, const ViewAxes& axes, MapViewKind kind,
                              int width, int height, const FramingOptions& options) {
  using namespace map_view_framing_detail;
  if (width < 16 || height < 16) throw Error("render: a map view needs at least 16x16 pixels");
  if (!(options.low_percentile >= 0 && options.low_percentile < options.high_percentile &&
        options.high_percentile <= 100 && options.margin >= 0 && options.margin < 0.45))
    throw Error("render: map view framing needs 0 <= low < high <= 100 percent and a margin in [0, 0.45)");

  RobustBox box = robust_box(points_w, anchors_w, axes, options);
  ViewAxes view_axes = axes;
  if (kind == MapViewKind::top) {
    // Seen from above there is no "behind": turn the picture so that the
    // map's longest horizontal extent runs along its longer side, forward
    // still upwards rather than downwards.
    view_axes.forward_w = across_major_axis(box.framed, axes, height > width);
    box = robust_box(points_w, anchors_w, view_axes, options);
  }
  const std::vector<Eigen::Vector3d>& framed = box.framed;
  const Eigen::Vector3d &lo = box.lo, &hi = box.hi;
  // A flat or single-point map still gets a box of some size.
  const double diagonal = std::max((hi - lo).norm(), 1e-3);
  const Eigen::Vector3d centre_w = box.R_box_w.transpose() * (0.5 * (lo + hi));

  // Stand back far enough that a 53-degree-wide view holds the box's points.
  const Eigen::Matrix3d R_c_w = view_rotation(view_axes, kind, options.elevation_deg);
  const double f0 = width;
  double distance = 0.0;
  for (const Eigen::Vector3d& p : framed) {
    const Eigen::Vector3d q = R_c_w * (p - centre_w);
    distance = std::max({distance, f0 * std::abs(q.x()) / (0.5 * width) - q.z(),
                         f0 * std::abs(q.y()) / (0.5 * height) - q.z(), 0.05 * diagonal - q.z()});
  }
  distance = std::max(distance, 0.05 * diagonal);

  // Fit focal length and principal point to the normalised image extent.
  Eigen::Vector2d n_lo = Eigen::Vector2d::Constant(std::numeric_limits<double>::infinity()), n_hi = -n_lo;
  for (const Eigen::Vector3d& p : framed) {
    const Eigen::Vector3d q = R_c_w * (p - centre_w) + Eigen::Vector3d(0, 0, distance);
    const Eigen::Vector2d n = q.head<2>() / q.z();
    n_lo = n_lo.cwiseMin(n);
    n_hi = n_hi.cwiseMax(n);
  }
  const Eigen::Vector2d extent = (n_hi - n_lo).cwiseMax(1e-6);
  const double usable = 1.0 - 2.0 * options.margin;
  const double f = std::min(usable * width / extent.x(), usable * height / extent.y());

  MapViewFraming framing;
  PinholeIntrinsics& k = framing.camera.intrinsics;
  k.width = width;
  k.height = height;
  k.fx = k.fy = f;
  k.cx = 0.5 * (width - 1) - f * 0.5 * (n_lo.x() + n_hi.x());
  k.cy = 0.5 * (height - 1) - f * 0.5 * (n_lo.y() + n_hi.y());
  framing.camera.T_w_c.linear() = R_c_w.transpose();
  framing.camera.T_w_c.translation() = centre_w - distance * R_c_w.row(2).transpose();
  framing.camera.near = 0.01 * distance;
  framing.box_diagonal = diagonal;
  return framing;
}

}  // namespace facadeslam::render
