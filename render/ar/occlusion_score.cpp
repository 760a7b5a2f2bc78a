#include "render/ar/occlusion_score.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace facadeslam::render::ar {
namespace {

constexpr double kHiddenMargin = 0.99;  // the other depth nearer by 1 %

bool nearer(float other, float object_z) {
  return other > 0.f && std::isfinite(other) && other < kHiddenMargin * object_z;
}

}  // namespace

cv::Mat object_depth(const VirtualObject& object, const Camera& camera, const Eigen::Isometry3d& T_c_w) {
  cv::Mat depth(camera.height(), camera.width(), CV_32FC1, cv::Scalar(std::numeric_limits<float>::infinity()));
  // Only the pixels inside the projected corners' box, when all are in front.
  int x0 = 0, y0 = 0, x1 = camera.width() - 1, y1 = camera.height() - 1;
  bool all_in_front = true;
  double u0 = 1e300, v0 = 1e300, u1 = -1e300, v1 = -1e300;
  for (const Eigen::Vector3d& corner : object.corners_w()) {
    const Eigen::Vector3d p_c = T_c_w * corner;
    if (p_c.z() <= 1e-9) {
      all_in_front = false;
      break;
    }
    const Eigen::Vector2d px = camera.project(p_c);
    u0 = std::min(u0, px.x()), v0 = std::min(v0, px.y()), u1 = std::max(u1, px.x()), v1 = std::max(v1, px.y());
  }
  if (all_in_front) {
    // A margin for the distortion between the corners.
    const double margin = 2.0 + 0.05 * std::max(u1 - u0, v1 - v0);
    x0 = std::max(x0, static_cast<int>(std::floor(u0 - margin)));
    y0 = std::max(y0, static_cast<int>(std::floor(v0 - margin)));
    x1 = std::min(x1, static_cast<int>(std::ceil(u1 + margin)));
    y1 = std::min(y1, static_cast<int>(std::ceil(v1 + margin)));
  }
  const Eigen::Isometry3d T_o_c = object.T_w_o.inverse() * T_c_w.inverse();
  const Eigen::Vector3d eye_o = T_o_c.translation();
  const double h = 0.5 * object.size;
  const Eigen::Vector3d low(-h, -h, 0.0), high(h, h, object.size);
  for (int y = y0; y <= y1; ++y) {
    float* row = depth.ptr<float>(y);
    for (int x = x0; x <= x1; ++x) {
      const Eigen::Vector3d ray_c = camera.unproject(Eigen::Vector2d(x, y));
      const Eigen::Vector3d direction = T_o_c.linear() * ray_c;
      double enter = 0.0, leave = std::numeric_limits<double>::infinity();
      bool hit = true;
      for (int axis = 0; axis < 3 && hit; ++axis) {
        if (std::abs(direction[axis]) < 1e-300) {
          hit = eye_o[axis] >= low[axis] && eye_o[axis] <= high[axis];
          continue;
        }
        double t0 = (low[axis] - eye_o[axis]) / direction[axis], t1 = (high[axis] - eye_o[axis]) / direction[axis];
        if (t0 > t1) std::swap(t0, t1);
        enter = std::max(enter, t0);
        leave = std::min(leave, t1);
        hit = enter <= leave;
      }
      if (hit && enter > 0.0) row[x] = static_cast<float>(enter * ray_c.z());
    }
  }
  return depth;
}

bool leaves_object_visible(const cv::Mat& object_z, const cv::Mat& occluder_z) {
  const bool occluded = occluder_z.size() == object_z.size();
  for (int y = 0; y < object_z.rows; ++y) {
    const float* o = object_z.ptr<float>(y);
    const float* r = occluded ? occluder_z.ptr<float>(y) : nullptr;
    for (int x = 0; x < object_z.cols; ++x)
      if (std::isfinite(o[x]) && !(r && nearer(r[x], o[x]))) return true;
  }
  return false;
}

void OcclusionScore::add_frame(const cv::Mat& object_z, const cv::Mat& occluder_z, const cv::Mat& truth_z) {
  std::size_t object = 0, render_hidden = 0, truth_hidden = 0, both = 0;
  for (int y = 0; y < object_z.rows; ++y) {
    const float* o = object_z.ptr<float>(y);
    const float* r = occluder_z.ptr<float>(y);
    const float* t = truth_z.ptr<float>(y);
    for (int x = 0; x < object_z.cols; ++x) {
      if (!std::isfinite(o[x])) continue;
      ++object;
      const bool by_render = nearer(r[x], o[x]), by_truth = nearer(t[x], o[x]);
      render_hidden += by_render;
      truth_hidden += by_truth;
      both += by_render && by_truth;
    }
  }
  ++frames_;
  if (object > render_hidden) ++frames_visible_;
  both_ += static_cast<double>(both);
  either_ += static_cast<double>(render_hidden + truth_hidden - both);
  object_ += static_cast<double>(object);
  render_hidden_ += static_cast<double>(render_hidden);
  truth_hidden_ += static_cast<double>(truth_hidden);
  if (object == 0) return;
  const double render_share = static_cast<double>(render_hidden) / static_cast<double>(object);
  const double truth_share = static_cast<double>(truth_hidden) / static_cast<double>(object);
  if (last_render_share_) {
    flicker_render_ += std::abs(render_share - *last_render_share_);
    flicker_truth_ += std::abs(truth_share - *last_truth_share_);
    ++changes_;
  }
  last_render_share_ = render_share;
  last_truth_share_ = truth_share;
}

std::optional<double> OcclusionScore::iou() const {
  if (either_ <= 0) return std::nullopt;
  return both_ / either_;
}

}  // namespace facadeslam::render::ar
