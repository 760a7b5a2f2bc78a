#include "render/ar/virtual_object.hpp"
#include "core/util/median.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace facadeslam::render::ar {
// Named, so that the unity build's other render files cannot clash with these.
namespace virtual_object_detail {
namespace {

// A face as its corner at face_uv (0, 0) and the edges to (1, 0) and (0, 1),
// in the object frame of a unit cube standing on z = 0.
struct Face {
  Eigen::Vector3d origin, u, v, normal;
};

const std::array<Face, 6>& unit_faces() {
  using V = Eigen::Vector3d;
  static const std::array<Face, 6> faces{{
      {V(-0.5, -0.5, 1), V(1, 0, 0), V(0, 1, 0), V(0, 0, 1)},   // top
      {V(-0.5, -0.5, 0), V(0, 1, 0), V(1, 0, 0), V(0, 0, -1)},  // bottom, on the plane
      {V(0.5, -0.5, 0), V(0, 1, 0), V(0, 0, 1), V(1, 0, 0)},    // +x
      {V(-0.5, 0.5, 0), V(0, -1, 0), V(0, 0, 1), V(-1, 0, 0)},  // -x
      {V(0.5, 0.5, 0), V(-1, 0, 0), V(0, 0, 1), V(0, 1, 0)},    // +y
      {V(-0.5, -0.5, 0), V(1, 0, 0), V(0, 0, 1), V(0, -1, 0)},  // -y
  }};
  return faces;
}

}  // namespace
}  // namespace virtual_object_detail

std::array<Eigen::Vector3d, 8> VirtualObject::corners_w() const {
  std::array<Eigen::Vector3d, 8> corners;
  const double h = 0.5 * size;
  const double xy[4][2] = {{-h, -h}, {h, -h}, {h, h}, {-h, h}};
  for (int i = 0; i < 4; ++i) {
    corners[i] = T_w_o * Eigen::Vector3d(xy[i][0], xy[i][1], 0.0);
    corners[i + 4] = T_w_o * Eigen::Vector3d(xy[i][0], xy[i][1], size);
  }
  return corners;
}

std::vector<VirtualObject::FacePoint> VirtualObject::checker_corners_w() const {
  std::vector<FacePoint> out;
  for (const virtual_object_detail::Face& face : virtual_object_detail::unit_faces())
    for (int i = 1; i < checker_squares; ++i)
      for (int j = 1; j < checker_squares; ++j) {
        const double a = double(i) / checker_squares, b = double(j) / checker_squares;
        const Eigen::Vector3d p_o = size * (face.origin + a * face.u + b * face.v);
        out.push_back({T_w_o * p_o, T_w_o.linear() * face.normal});
      }
  return out;
}

bool hides(const VirtualObject& object, const Eigen::Vector3d& eye_w, const Eigen::Vector3d& p_w) {
  // Slab test in the object frame, on the segment eye + t (p - eye), t in [0, 1].
  const Eigen::Isometry3d T_o_w = object.T_w_o.inverse();
  const Eigen::Vector3d start = T_o_w * eye_w, direction = T_o_w.linear() * (p_w - eye_w);
  const double h = 0.5 * object.size;
  const Eigen::Vector3d low(-h, -h, 0.0), high(h, h, object.size);
  double enter = 0.0, leave = 1.0;
  for (int axis = 0; axis < 3; ++axis) {
    if (std::abs(direction[axis]) < 1e-300) {
      if (start[axis] < low[axis] || start[axis] > high[axis]) return false;
      continue;
    }
    double t0 = (low[axis] - start[axis]) / direction[axis], t1 = (high[axis] - start[axis]) / direction[axis];
    if (t0 > t1) std::swap(t0, t1);
    enter = std::max(enter, t0);
    leave = std::min(leave, t1);
    if (enter > leave) return false;
  }
  // The segment meets the box; p_w is hidden unless the box starts at p_w
  // itself (a point on the surface facing the eye). The margin is relative,
  // for rounding.
  return enter < 1.0 - 1e-9;
}

std::vector<ObjectVertex> object_triangles(const VirtualObject& object) {
  std::vector<ObjectVertex> out;
  out.reserve(36);
  for (const virtual_object_detail::Face& face : virtual_object_detail::unit_faces()) {
    const auto corner = [&](double a, double b) {
      return ObjectVertex{object.T_w_o * (object.size * (face.origin + a * face.u + b * face.v)),
                          object.T_w_o.linear() * face.normal, Eigen::Vector2d(a, b)};
    };
    const ObjectVertex c00 = corner(0, 0), c10 = corner(1, 0), c11 = corner(1, 1), c01 = corner(0, 1);
    for (const ObjectVertex& v : {c00, c10, c11, c00, c11, c01}) out.push_back(v);
  }
  return out;
}

std::optional<VirtualObject> place_on_plane(const PlaneFit& fit, const std::vector<Eigen::Vector3d>& points_w,
                                            const Eigen::Isometry3d& T_w_ref, const PlacementOptions& options) {
  const Eigen::Vector3d camera_w = T_w_ref.translation();
  Plane plane = fit.plane;
  double camera_height = plane.signed_distance(camera_w);
  if (std::abs(camera_height) < 1e-12) return std::nullopt;
  if (camera_height < 0) {  // up is the cameras' side
    plane.normal_w = -plane.normal_w;
    plane.offset = -plane.offset;
    camera_height = -camera_height;
  }
  // The anchor: the median of the inliers nearest the reference camera's
  // optical axis (the fifth of those in front of it with the smallest angle
  // to it), so that the object starts near the middle of that view, on a
  // part of the plane the map has points on.
  const Eigen::Isometry3d T_ref_w = T_w_ref.inverse();
  std::vector<std::pair<double, std::size_t>> by_angle;
  for (const std::size_t i : fit.inliers) {
    const Eigen::Vector3d p_ref = T_ref_w * points_w[i];
    if (p_ref.z() > 0.0) by_angle.emplace_back(p_ref.head<2>().norm() / p_ref.z(), i);
  }
  if (by_angle.empty())
    for (const std::size_t i : fit.inliers) by_angle.emplace_back(0.0, i);
  if (by_angle.empty()) return std::nullopt;
  const std::size_t keep = std::max<std::size_t>(1, by_angle.size() / 5);
  std::partial_sort(by_angle.begin(), by_angle.begin() + static_cast<std::ptrdiff_t>(keep), by_angle.end());
  Eigen::Vector3d anchor;
  for (int axis = 0; axis < 3; ++axis) {
    std::vector<double> values;
    for (std::size_t k = 0; k < keep; ++k) values.push_back(points_w[by_angle[k].second][axis]);
    anchor[axis] = median(std::move(values));
  }
  anchor -= plane.signed_distance(anchor) * plane.normal_w;

  const Eigen::Vector3d z = plane.normal_w;
  Eigen::Vector3d x = T_w_ref.linear().col(0);  // the camera's right
  x -= x.dot(z) * z;
  if (x.norm() < 1e-6) {  // the camera's x axis is the normal: use its optical axis
    x = T_w_ref.linear().col(2);
    x -= x.dot(z) * z;
  }
  x = Eigen::AngleAxisd(options.yaw_deg * std::numbers::pi / 180.0, z) * x.normalized();
  VirtualObject object;
  object.T_w_o.linear().col(0) = x;
  object.T_w_o.linear().col(1) = z.cross(x);
  object.T_w_o.linear().col(2) = z;
  object.T_w_o.translation() = anchor;
  object.size = options.size_fraction * (anchor - camera_w).norm();
  if (!(object.size > 0.0)) return std::nullopt;
  return object;
}

}  // namespace facadeslam::render::ar
