#include "mapmaker/ground_gauge.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <spdlog/spdlog.h>

#include "core/util/angles.hpp"

namespace facadeslam {
namespace {

// Axes of the road under the camera: the normal (down), forward (the optical
// axis along the road) and lateral.
struct RoadFrame {
  Eigen::Vector3d normal, forward, lateral;

  explicit RoadFrame(const Eigen::Vector3d& n) : normal(n) {
    const Eigen::Vector3d z = Eigen::Vector3d::UnitZ();
    forward = (z - z.dot(n) * n).normalized();
    lateral = n.cross(forward);
  }

  // In the lane ahead of a camera `height` above the road.
  bool in_lane(const Eigen::Vector3d& p_c, double height, const GroundGaugeOptions& options) const {
    const double ahead = forward.dot(p_c);
    return ahead > -options.max_behind * height && ahead < options.max_ahead * height &&
           std::abs(lateral.dot(p_c)) < options.lane_half_width * height;
  }
};

struct PooledPoint {
  Eigen::Vector3d p_c;
  std::size_t keyframe;
};

struct PlaneFit {
  Eigen::Vector3d normal;
  double height = 0.0;
  std::vector<std::size_t> inliers;  // indices into the pooled points
};

bool plausible_normal(const Eigen::Vector3d& n, const GroundGaugeOptions& options) {
  return n.allFinite() && n.y() >= std::cos(deg_to_rad(options.max_tilt_deg));
}

std::vector<std::size_t> plane_inliers(const std::vector<PooledPoint>& pooled, const Eigen::Vector3d& n, double height,
                                       const GroundGaugeOptions& options) {
  std::vector<std::size_t> inliers;
  const RoadFrame road(n);
  for (std::size_t i = 0; i < pooled.size(); ++i) {
    const Eigen::Vector3d& p = pooled[i].p_c;
    if (std::abs(n.dot(p) - height) < options.reference_inlier_band * height && road.in_lane(p, height, options))
      inliers.push_back(i);
  }
  return inliers;
}

// The least-squares plane through the inliers, oriented downwards.
std::optional<PlaneFit> refit(const std::vector<PooledPoint>& pooled, const std::vector<std::size_t>& inliers,
                              const GroundGaugeOptions& options) {
  if (inliers.size() < 3) return std::nullopt;
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const std::size_t i : inliers) centroid += pooled[i].p_c;
  centroid /= static_cast<double>(inliers.size());
  Eigen::Matrix3d scatter = Eigen::Matrix3d::Zero();
  for (const std::size_t i : inliers) {
    const Eigen::Vector3d d = pooled[i].p_c - centroid;
    scatter += d * d.transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen(scatter);
  Eigen::Vector3d n = eigen.eigenvectors().col(0);
  if (n.y() < 0.0) n = -n;
  const double height = n.dot(centroid);
  if (!plausible_normal(n, options) || !(height > 0.0)) return std::nullopt;
  return PlaneFit{n, height, plane_inliers(pooled, n, height, options)};
}

// Did the cameras move like a vehicle's over the plane (normal_c, height)?
// Forward, the normal the same in the world from every keyframe, the centres at the
// same height above it.
bool moved_like_a_vehicle(const std::vector<GroundView>& views, const Eigen::Vector3d& normal_c, double height,
                          const GroundGaugeOptions& options) {
  const double min_cos = std::cos(deg_to_rad(options.max_normal_spread_deg));
  const SE3d& first = views.front().T_c_w;
  const Eigen::Vector3d normal_w = first.so3().inverse() * normal_c;
  // The plane in the world: normal_w . x = offset, from the first keyframe.
  const double offset = normal_w.dot(first.inverse().translation()) + height;
  const Eigen::Vector3d travel_c = first * views.back().T_c_w.inverse().translation();
  if (travel_c.norm() <= 0.0 || travel_c.z() < travel_c.norm() * std::cos(deg_to_rad(options.max_motion_angle_deg))) {
    spdlog::debug("no ground gauge from {} keyframes: they did not travel along the optical axis", views.size());
    return false;
  }
  for (const GroundView& view : views) {
    const Eigen::Vector3d n_w = view.T_c_w.so3().inverse() * normal_c;
    if (n_w.dot(normal_w) < min_cos) {
      spdlog::debug("no ground gauge from {} keyframes: the cameras tilted over the plane", views.size());
      return false;
    }
    const double centre_height = offset - normal_w.dot(view.T_c_w.inverse().translation());
    if (std::abs(centre_height - height) > options.max_height_spread * height) {
      spdlog::debug("no ground gauge from {} keyframes: the cameras were not at one height over the plane",
                    views.size());
      return false;
    }
  }
  return true;
}

}  // namespace

std::optional<GroundReference> fit_ground_reference(const std::vector<GroundView>& views,
                                                    const GroundGaugeOptions& options) {
  std::vector<PooledPoint> pooled;
  for (std::size_t k = 0; k < views.size(); ++k)
    for (const Eigen::Vector3d& p : views[k].points_c)
      if (p.allFinite() && p.z() > 0.0 && p.y() > 0.0) pooled.push_back({p, k});
  if (pooled.size() < options.min_reference_inliers) return std::nullopt;

  constexpr int kIterations = 500;
  std::mt19937 rng(7);  // fixed: --sync runs are reproducible
  std::uniform_int_distribution<std::size_t> pick(0, pooled.size() - 1);
  std::optional<PlaneFit> best;
  for (int it = 0; it < kIterations; ++it) {
    const std::size_t a = pick(rng), b = pick(rng), c = pick(rng);
    if (a == b || b == c || a == c) continue;
    Eigen::Vector3d n = (pooled[b].p_c - pooled[a].p_c).cross(pooled[c].p_c - pooled[a].p_c);
    if (n.norm() < 1e-12) continue;
    n.normalize();
    if (n.y() < 0.0) n = -n;
    const double height = n.dot(pooled[a].p_c);
    if (!plausible_normal(n, options) || !(height > 0.0)) continue;
    std::vector<std::size_t> inliers = plane_inliers(pooled, n, height, options);
    if (!best || inliers.size() > best->inliers.size()) best = PlaneFit{n, height, std::move(inliers)};
  }
  for (int round = 0; round < 2 && best; ++round)
    if (auto refined = refit(pooled, best->inliers, options); refined && refined->inliers.size() >= 3)
      best = std::move(refined);
  if (!best || best->inliers.size() < options.min_reference_inliers) {
    spdlog::debug("no ground gauge from {} keyframes: no plane below the cameras with {} points ({} at most)",
                  views.size(), options.min_reference_inliers, best ? best->inliers.size() : 0);
    return std::nullopt;
  }
  // The plane must be the ground under several keyframes, not one patch of
  // one of them.
  std::vector<std::size_t> per_keyframe(views.size(), 0);
  for (const std::size_t i : best->inliers) ++per_keyframe[pooled[i].keyframe];
  const auto supporting =
      std::count_if(per_keyframe.begin(), per_keyframe.end(), [&](std::size_t n) { return n >= options.min_inliers; });
  if (supporting < 2) {
    spdlog::debug("no ground gauge from {} keyframes: the plane lies under fewer than 2 of them", views.size());
    return std::nullopt;
  }
  if (!moved_like_a_vehicle(views, best->normal, best->height, options)) return std::nullopt;
  return GroundReference{best->normal, views.front().T_c_w.so3().inverse() * best->normal, best->height,
                         best->inliers.size()};
}

std::optional<GroundCluster> find_ground(const std::vector<Eigen::Vector3d>& points_c, const GroundReference& reference,
                                         double expected_height, const GroundGaugeOptions& options) {
  const RoadFrame road(reference.normal_c);
  struct Candidate {
    double height;
    double ahead;
    std::size_t index;
  };
  std::vector<Candidate> candidates;
  const double low = (1.0 - options.search_window) * expected_height;
  const double high = (1.0 + options.search_window) * expected_height;
  for (std::size_t i = 0; i < points_c.size(); ++i) {
    const Eigen::Vector3d& p = points_c[i];
    const double height = reference.normal_c.dot(p);
    if (p.allFinite() && height >= low && height <= high && road.in_lane(p, expected_height, options))
      candidates.push_back({height, road.forward.dot(p), i});
  }
  if (candidates.size() < options.min_inliers) return std::nullopt;
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    return a.height < b.height || (a.height == b.height && a.index < b.index);
  });
  // The densest cluster of heights (a window of width 2 x band).
  const double width = 2.0 * options.inlier_band * expected_height;
  std::size_t best_begin = 0, best_count = 0;
  for (std::size_t begin = 0, end = 0; begin < candidates.size(); ++begin) {
    end = std::max(end, begin);
    while (end < candidates.size() && candidates[end].height - candidates[begin].height <= width) ++end;
    if (end - begin > best_count) {
      best_count = end - begin;
      best_begin = begin;
    }
  }
  const double height = candidates[best_begin + best_count / 2].height;
  std::vector<Candidate> inliers;
  for (const Candidate& c : candidates)
    if (std::abs(c.height - height) <= options.inlier_band * expected_height) inliers.push_back(c);
  if (inliers.size() < options.min_inliers) return std::nullopt;
  // The nearest are the best triangulated.
  std::sort(inliers.begin(), inliers.end(), [](const Candidate& a, const Candidate& b) {
    return a.ahead < b.ahead || (a.ahead == b.ahead && a.index < b.index);
  });
  if (inliers.size() > options.max_points_per_keyframe) inliers.resize(options.max_points_per_keyframe);
  GroundCluster cluster{height, {}};
  for (const Candidate& c : inliers) cluster.inliers.push_back(c.index);
  return cluster;
}

void GroundGauge::try_reference(std::size_t keyframes, const std::function<std::vector<GroundView>()>& views) {
  if (!options_.enabled || reference_ || gave_up_ || keyframes < options_.reference_keyframes) return;
  if (keyframes > options_.max_reference_keyframes) {
    gave_up_ = true;
    return;
  }
  reference_ = fit_ground_reference(views(), options_);
}

std::size_t GroundGauge::constrain(BaProblem& problem, bool fixed_too) {
  if (!reference_) return 0;
  // The road under a keyframe is measured by the keyframes around it more
  // than by itself (KITTI's asphalt gives each keyframe ~5 corners in its
  // lane): every point taking part is a candidate for every keyframe.
  std::vector<char> observed(problem.points.size(), 0);
  for (const BaObservation& obs : problem.observations) observed[obs.point] = 1;
  std::vector<std::size_t> candidates;
  for (std::size_t p = 0; p < problem.points.size(); ++p)
    if (observed[p]) candidates.push_back(p);
  const double point_sigma = options_.point_sigma * reference_->height;
  const double share =
      (options_.point_sigma / options_.keyframe_sigma) * (options_.point_sigma / options_.keyframe_sigma);
  const double min_cos_tilt = std::cos(deg_to_rad(options_.max_keyframe_tilt_deg));
  std::size_t constrained = 0;
  std::vector<Eigen::Vector3d> points_c(candidates.size());
  for (std::size_t k = 0; k < problem.keyframes.size(); ++k) {
    const BaKeyFrame& kf = problem.keyframes[k];
    if (kf.fixed && !fixed_too) continue;
    if ((kf.T_c_w.so3().inverse() * reference_->normal_c).dot(reference_->normal_w) < min_cos_tilt) continue;
    for (std::size_t i = 0; i < candidates.size(); ++i) points_c[i] = kf.T_c_w * problem.points[candidates[i]].p_w;
    // Expected: this keyframe's last height, else the one before it, else the reference.
    double expected = reference_->height;
    if (const auto it = heights_.upper_bound(kf.id); it != heights_.begin()) expected = std::prev(it)->second;
    const auto ground = find_ground(points_c, *reference_, expected, options_);
    if (!ground) continue;
    heights_[kf.id] = ground->height;
    const double weight = share / static_cast<double>(ground->inliers.size());
    for (const std::size_t i : ground->inliers)
      problem.ground.push_back({k, candidates[i], reference_->normal_c, reference_->height, point_sigma, weight});
    ++constrained;
  }
  return constrained;
}

void GroundGauge::reset() {
  reference_.reset();
  gave_up_ = false;
  heights_.clear();
}

}  // namespace facadeslam
