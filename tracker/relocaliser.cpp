#include "tracker/relocaliser.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Dense>

namespace facadeslam {
namespace {

// SBI pixel <-> level-0 pixel, with the pyramid's pixel-centre convention.
constexpr double kSbiScale = static_cast<double>(1 << kSbiLevel);
Eigen::Vector2d sbi_to_level0(const Eigen::Vector2d& x) { return (x.array() + 0.5) * kSbiScale - 0.5; }
Eigen::Vector2d level0_to_sbi(const Eigen::Vector2d& x) { return (x.array() + 0.5) / kSbiScale - 0.5; }

}  // namespace

SO3d rotation_from_sbi_motion(const Se2Motion& motion, const Camera& camera, cv::Size sbi_size) {
  const Eigen::Vector2d c((sbi_size.width - 1) / 2.0, (sbi_size.height - 1) / 2.0);
  const double ct = std::cos(motion.theta), st = std::sin(motion.theta);
  // Sample current-frame pixels on a 3x3 grid and where the motion says they
  // were in the keyframe.
  std::vector<Eigen::Vector3d> rays_kf;
  std::vector<Eigen::Vector2d> pixels_cur;
  for (int gy = 0; gy < 3; ++gy)
    for (int gx = 0; gx < 3; ++gx) {
      const Eigen::Vector2d x_cur((0.2 + 0.3 * gx) * (camera.width() - 1), (0.2 + 0.3 * gy) * (camera.height() - 1));
      const Eigen::Vector2d d = level0_to_sbi(x_cur) - c;
      const Eigen::Vector2d w(ct * d.x() - st * d.y() + c.x() + motion.t.x(),
                              st * d.x() + ct * d.y() + c.y() + motion.t.y());
      rays_kf.push_back(camera.unproject(sbi_to_level0(w)));
      pixels_cur.push_back(x_cur);
    }
  SO3d R;
  for (int it = 0; it < 10; ++it) {
    Eigen::Matrix3d H = Eigen::Matrix3d::Zero();
    Eigen::Vector3d g = Eigen::Vector3d::Zero();
    for (std::size_t i = 0; i < rays_kf.size(); ++i) {
      const Eigen::Vector3d p = R * rays_kf[i];
      if (p.z() <= 1e-6) continue;
      const Eigen::Vector2d r = camera.project(p) - pixels_cur[i];
      // Left update R <- exp(w) R: d p / d w = -hat(p).
      const Eigen::Matrix<double, 2, 3> J = camera.project_jacobian(p) * (-SO3d::hat(p));
      H += J.transpose() * J;
      g += J.transpose() * r;
    }
    const Eigen::Vector3d step = H.ldlt().solve(-g);
    if (!step.allFinite()) break;
    R = SO3d::exp(step) * R;
    if (step.norm() < 1e-9) break;
  }
  return R;
}

std::vector<KeyFrameSnapshot> keyframes_by_similarity(const cv::Mat& current_sbi,
                                                      std::vector<KeyFrameSnapshot> keyframes) {
  std::vector<std::pair<double, std::size_t>> order;
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    const cv::Mat& sbi = keyframes[i].keyframe->small_blurred();
    order.emplace_back(
        sbi.size() == current_sbi.size() ? sbi_difference(sbi, current_sbi) : std::numeric_limits<double>::infinity(),
        i);
  }
  std::stable_sort(order.begin(), order.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<KeyFrameSnapshot> out;
  out.reserve(keyframes.size());
  for (const auto& [difference, i] : order) out.push_back(std::move(keyframes[i]));
  return out;
}

std::optional<RelocalisationCandidate> find_relocalisation_candidate(const cv::Mat& current_sbi,
                                                                     const std::vector<KeyFrameSnapshot>& keyframes,
                                                                     const Camera& camera,
                                                                     const RelocaliserOptions& options) {
  double best = std::numeric_limits<double>::infinity();
  std::size_t best_index = 0;
  for (std::size_t i = 0; i < keyframes.size(); ++i) {
    const cv::Mat& sbi = keyframes[i].keyframe->small_blurred();
    if (sbi.size() != current_sbi.size()) continue;
    const double d = sbi_difference(sbi, current_sbi);
    if (d < best) {
      best = d;
      best_index = i;
    }
  }
  if (!std::isfinite(best)) return std::nullopt;
  const double rms = std::sqrt(best / static_cast<double>(current_sbi.total()));
  if (rms > options.max_rms_difference) return std::nullopt;

  const KeyFrameSnapshot& kf = keyframes[best_index];
  const Se2Motion motion = align_small_blurry_images(kf.keyframe->small_blurred(), current_sbi);
  const SO3d R_cur_kf = rotation_from_sbi_motion(motion, camera, current_sbi.size());
  const SE3d T_c_w = SE3d(R_cur_kf, Eigen::Vector3d::Zero()) * kf.T_c_w;
  return RelocalisationCandidate{kf.keyframe, T_c_w, best};
}

}  // namespace facadeslam
