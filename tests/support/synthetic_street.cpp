#include "tests/support/synthetic_street.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

// The draws are sequenced by hand, last coefficient first: the arguments of
// one call are evaluated in an unspecified order (GCC right to left, clang
// left to right), and the tests' thresholds were set on GCC's scenes; the
// scenes must not depend on the compiler.
Eigen::Vector3d random_unit_vector(std::mt19937& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector3d v;
  do {
    for (int k = 2; k >= 0; --k) v[k] = normal(rng);
  } while (v.norm() < 1e-6);
  return v.normalized();
}

}  // namespace

StreetScene make_street_scene(const StreetSceneOptions& options, const Camera& camera) {
  if (options.keyframes < 2 || options.points < 1 || options.levels < 1 || !(options.spacing > 0.0) ||
      !(options.facade_distance > 0.0) || !(options.relief >= 0.0))
    throw Error("synthetic street: needs >= 2 keyframes, >= 1 point, >= 1 level and positive distances");
  std::mt19937 rng(options.seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);

  StreetScene scene;
  for (int i = 0; i < options.keyframes; ++i) {
    const Eigen::Vector3d centre(i * options.spacing, options.height_jitter * unit(rng), 0.0);
    const SO3d R_c_w = SO3d::exp(options.rotation_jitter * random_unit_vector(rng));
    scene.true_T_c_w.push_back(SE3d(R_c_w, -(R_c_w * centre)));
  }

  // The facade span: the street length plus the half-width seen at the
  // facade, and the height the image covers there.
  const double half_width = options.facade_distance * (camera.width() / 2.0) / camera.fx();
  const double half_height = options.facade_distance * (camera.height() / 2.0) / camera.fy();
  std::uniform_real_distribution<double> along(-half_width, (options.keyframes - 1) * options.spacing + half_width);
  std::uniform_int_distribution<int> level_of(0, options.levels - 1);

  for (int j = 0; j < options.points; ++j) {
    // Last coordinate first (see random_unit_vector).
    const double z = options.facade_distance + options.relief * unit(rng);
    const double y = half_height * unit(rng);
    const Eigen::Vector3d p_w(along(rng), y, z);
    std::vector<BaObservation> seen;
    for (int i = 0; i < options.keyframes; ++i) {
      const Eigen::Vector3d p_c = scene.true_T_c_w[i] * p_w;
      if (p_c.z() <= 0.1) continue;
      const Eigen::Vector2d px = camera.project(p_c);
      if (!camera.in_image(px, 2.0)) continue;
      BaObservation obs;
      obs.keyframe = static_cast<std::size_t>(i);
      obs.point = scene.true_p_w.size();
      obs.pixel = px;
      obs.level = level_of(rng);
      seen.push_back(obs);
    }
    if (seen.size() < 2) continue;
    scene.problem.points.push_back({scene.true_p_w.size(), p_w, false});
    scene.true_p_w.push_back(p_w);
    scene.problem.observations.insert(scene.problem.observations.end(), seen.begin(), seen.end());
  }
  for (int i = 0; i < options.keyframes; ++i)
    scene.problem.keyframes.push_back({static_cast<std::uint64_t>(i), scene.true_T_c_w[i], false});
  return scene;
}

void perturb_free_blocks(BaProblem& problem, double rotation_rad, double translation_m, double point_m, unsigned seed) {
  std::mt19937 rng(seed);
  for (BaKeyFrame& kf : problem.keyframes) {
    if (kf.fixed) continue;
    SE3d::Tangent delta;
    delta << translation_m * random_unit_vector(rng), rotation_rad * random_unit_vector(rng);
    // exp(delta) has rotation angle rotation_rad; its translation is J_l rho
    // (norm close to translation_m): the perturbation the manifold sees.
    kf.T_c_w = SE3d::exp(delta) * kf.T_c_w;
  }
  for (BaPoint& point : problem.points)
    if (!point.fixed) point.p_w += point_m * random_unit_vector(rng);
}

void add_pixel_noise(BaProblem& problem, double sigma_px, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> normal(0.0, 1.0);
  for (BaObservation& obs : problem.observations) {
    const double sigma = sigma_px * std::ldexp(1.0, obs.level);
    const double dy = normal(rng);  // drawn first (see random_unit_vector)
    obs.pixel += sigma * Eigen::Vector2d(normal(rng), dy);
  }
}

std::vector<std::size_t> add_gross_outliers(BaProblem& problem, double fraction, double offset_px, unsigned seed) {
  std::mt19937 rng(seed);
  std::vector<std::size_t> indices(problem.observations.size());
  for (std::size_t i = 0; i < indices.size(); ++i) indices[i] = i;
  std::shuffle(indices.begin(), indices.end(), rng);
  indices.resize(static_cast<std::size_t>(std::lround(fraction * static_cast<double>(indices.size()))));
  std::sort(indices.begin(), indices.end());
  std::uniform_real_distribution<double> angle(0.0, 2.0 * std::numbers::pi);
  for (std::size_t i : indices) {
    const double a = angle(rng);
    problem.observations[i].pixel += offset_px * Eigen::Vector2d(std::cos(a), std::sin(a));
  }
  return indices;
}

}  // namespace facadeslam
