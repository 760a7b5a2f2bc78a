// Bundle adjustment as the map maker runs it: a local BA (newest keyframe +
// 4 neighbours free, the keyframes observing their points fixed, ~2k points)
// and global BAs of 20/50/100 keyframes (~150 points each), 10 Levenberg–
// Marquardt iterations each, on a synthetic street (mapmaker/ba/synthetic_street).
//
// The peer, measured in the same run on the same problem: the "textbook"
// Ceres BA, a pose block of 6 values [angle-axis, translation] without a
// manifold and ceres::AngleAxisRotatePoint in an auto-diff functor, with the
// same camera model, loss, linear solver, ordering and iteration count. The
// figure to read is our time / the peer's.
#include <array>
#include <cmath>
#include <map>
#include <memory>
#include <utility>
#include <variant>
#include <vector>

#include <benchmark/benchmark.h>
#include <ceres/autodiff_cost_function.h>
#include <ceres/loss_function.h>
#include <ceres/ordered_groups.h>
#include <ceres/problem.h>
#include <ceres/rotation.h>
#include <ceres/solver.h>

#include "mapmaker/ba/ba_selection.hpp"
#include "mapmaker/ba/bundle_adjuster.hpp"
#include "mapmaker/ba/reprojection_cost.hpp"
#include "tests/support/synthetic_street.hpp"

namespace {

using namespace facadeslam;

constexpr int kIterations = 10;

const Camera& camera() {
  static const Camera cam = [] {
    PinholeRadTan model;
    model.fx = 500.0;
    model.fy = 500.0;
    model.cx = 319.5;
    model.cy = 239.5;
    model.k1 = -0.08;
    model.k2 = 0.01;
    return Camera(640, 480, model);
  }();
  return cam;
}

// Noise and a perturbed start so that every iteration does real work.
void make_realistic(BaProblem& problem) {
  add_pixel_noise(problem, 0.5, 2);
  perturb_free_blocks(problem, 0.01, 0.02, 0.05, 3);
}

// Local BA: a dense stretch of street (PTAM adds keyframes every ~10 % of
// the scene depth), the newest keyframe and its `neighbours` nearest
// neighbours free (the map maker's default: 4), `points` points in the
// street. The BaProblem is built from local_ba_selection exactly as the map
// maker would build it from the Map.
const BaProblem& local_problem(int neighbours = 4, int points = 2700) {
  static std::map<std::pair<int, int>, BaProblem> cache;
  const auto key = std::make_pair(neighbours, points);
  if (const auto it = cache.find(key); it != cache.end()) return it->second;
  const BaProblem problem = [&] {
    StreetSceneOptions options;
    options.keyframes = 15;
    options.spacing = 0.5;
    options.points = points;
    options.levels = 4;
    const StreetScene scene = make_street_scene(options, camera());
    const BaProblem& full = scene.problem;
    std::vector<KeyFrameCentre> centres;
    for (const BaKeyFrame& kf : full.keyframes) centres.push_back({kf.id, kf.T_c_w.inverse().translation()});
    std::vector<ObservationRef> refs;
    for (const BaObservation& obs : full.observations)
      refs.push_back({full.keyframes[obs.keyframe].id, full.points[obs.point].id});
    const BaSelection selection = local_ba_selection(centres, refs, full.keyframes.back().id,
                                                     LocalBaOptions{static_cast<std::size_t>(neighbours)});

    BaProblem local;
    std::map<std::size_t, std::size_t> keyframe_index, point_index;  // full -> local
    for (std::size_t i = 0; i < full.keyframes.size(); ++i) {
      const bool free = selection.free_keyframes.contains(full.keyframes[i].id);
      if (!free && !selection.fixed_keyframes.contains(full.keyframes[i].id)) continue;
      keyframe_index[i] = local.keyframes.size();
      local.keyframes.push_back({full.keyframes[i].id, full.keyframes[i].T_c_w, !free});
    }
    for (std::size_t j = 0; j < full.points.size(); ++j) {
      if (!selection.free_points.contains(full.points[j].id)) continue;
      point_index[j] = local.points.size();
      local.points.push_back(full.points[j]);
    }
    for (const BaObservation& obs : full.observations)
      if (keyframe_index.contains(obs.keyframe) && point_index.contains(obs.point))
        local.observations.push_back({keyframe_index[obs.keyframe], point_index[obs.point], obs.pixel, obs.level});
    make_realistic(local);
    return local;
  }();
  return cache.emplace(key, problem).first->second;
}

// Global BA: keyframes every 1.5 m, ~150 new points per keyframe, the first
// keyframe fixed and the last one's distance to it anchored.
const BaProblem& global_problem(int keyframes) {
  static std::map<int, BaProblem> cache;
  auto it = cache.find(keyframes);
  if (it != cache.end()) return it->second;
  StreetSceneOptions options;
  options.keyframes = keyframes;
  options.spacing = 1.5;
  options.points = 170 * keyframes;  // those seen by one keyframe only are dropped
  options.levels = 4;
  BaProblem problem = make_street_scene(options, camera()).problem;
  problem.keyframes.front().fixed = true;
  make_realistic(problem);
  problem.scale_anchor = BaScaleAnchor{problem.keyframes.size() - 1, 0};
  return cache.emplace(keyframes, std::move(problem)).first->second;
}

void report(benchmark::State& state, const BaProblem& problem) {
  std::size_t fixed = 0;
  for (const BaKeyFrame& kf : problem.keyframes) fixed += kf.fixed ? 1 : 0;
  state.counters["free_kf"] = static_cast<double>(problem.keyframes.size() - fixed);
  state.counters["fixed_kf"] = static_cast<double>(fixed);
  state.counters["points"] = static_cast<double>(problem.points.size());
  state.counters["obs"] = static_cast<double>(problem.observations.size());
}

BundleAdjusterOptions fixed_iterations(BaLinearSolver solver, int threads) {
  BundleAdjusterOptions options;
  options.max_iterations = kIterations;
  options.function_tolerance = 0.0;  // always run all iterations: a fair per-solve time
  options.gradient_tolerance = 0.0;
  options.parameter_tolerance = 0.0;
  options.solver = solver;
  options.num_threads = threads;
  return options;
}

void run_ours(benchmark::State& state, const BaProblem& input, const BundleAdjusterOptions& options) {
  const BundleAdjuster adjuster(options);
  BaResult result;
  for (auto _ : state) {
    state.PauseTiming();
    BaProblem problem = input;
    state.ResumeTiming();
    result = adjuster.solve(problem, camera());
    benchmark::DoNotOptimize(problem.points.data());
  }
  report(state, input);
  state.counters["iterations"] = result.iterations;
  state.counters["rms_px"] = result.final_rms_px;
}

// ---- the peer: textbook angle-axis parameterisation -------------------------

struct TextbookReprojection {
  PinholeRadTan model;
  Eigen::Vector2d pixel;
  double inv_sigma;

  template <class T>
  bool operator()(const T* camera_block, const T* point, T* residual) const {
    T p[3];
    ceres::AngleAxisRotatePoint(camera_block, point, p);
    const Eigen::Matrix<T, 3, 1> p_c(p[0] + camera_block[3], p[1] + camera_block[4], p[2] + camera_block[5]);
    const Eigen::Matrix<T, 2, 1> px = model.project(p_c);
    residual[0] = (px.x() - pixel.x()) * inv_sigma;
    residual[1] = (px.y() - pixel.y()) * inv_sigma;
    return true;
  }
};

void BM_ResidualJacobiansTextbook(benchmark::State& state) {
  const BaProblem& input = local_problem();
  const PinholeRadTan& model = std::get<PinholeRadTan>(camera().model());
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  for (const BaObservation& obs : input.observations)
    costs.emplace_back(new ceres::AutoDiffCostFunction<TextbookReprojection, 2, 6, 3>(
        new TextbookReprojection{model, obs.pixel, std::ldexp(1.0, -obs.level)}));
  std::vector<std::array<double, 6>> cameras(input.keyframes.size());
  for (std::size_t i = 0; i < cameras.size(); ++i) {
    const SE3d& pose = input.keyframes[i].T_c_w;
    const Eigen::Vector3d aa = pose.so3().log();
    cameras[i] = {aa.x(), aa.y(), aa.z(), pose.translation().x(), pose.translation().y(), pose.translation().z()};
  }
  double residual[2], d_camera[12], d_point[6];
  double* jacobians[] = {d_camera, d_point};
  for (auto _ : state) {
    for (std::size_t k = 0; k < costs.size(); ++k) {
      const BaObservation& obs = input.observations[k];
      const double* parameters[] = {cameras[obs.keyframe].data(), input.points[obs.point].p_w.data()};
      costs[k]->Evaluate(parameters, residual, jacobians);
      benchmark::DoNotOptimize(d_point[0]);
    }
  }
  state.counters["obs"] = static_cast<double>(costs.size());
}
BENCHMARK(BM_ResidualJacobiansTextbook)->Unit(benchmark::kMillisecond);

void run_textbook(benchmark::State& state, const BaProblem& input, ceres::LinearSolverType solver, int threads) {
  const PinholeRadTan& model = std::get<PinholeRadTan>(camera().model());
  ceres::CauchyLoss loss(BundleAdjusterOptions{}.loss_scale);
  int iterations = 0;
  for (auto _ : state) {
    std::vector<std::array<double, 6>> cameras(input.keyframes.size());
    std::vector<std::array<double, 3>> points(input.points.size());
    for (std::size_t i = 0; i < cameras.size(); ++i) {
      const SE3d& pose = input.keyframes[i].T_c_w;
      const Eigen::Vector3d aa = pose.so3().log();
      cameras[i] = {aa.x(), aa.y(), aa.z(), pose.translation().x(), pose.translation().y(), pose.translation().z()};
    }
    for (std::size_t j = 0; j < points.size(); ++j)
      points[j] = {input.points[j].p_w.x(), input.points[j].p_w.y(), input.points[j].p_w.z()};

    ceres::Problem::Options problem_options;
    problem_options.loss_function_ownership = ceres::DO_NOT_TAKE_OWNERSHIP;
    ceres::Problem problem(problem_options);
    for (const BaObservation& obs : input.observations)
      problem.AddResidualBlock(new ceres::AutoDiffCostFunction<TextbookReprojection, 2, 6, 3>(
                                   new TextbookReprojection{model, obs.pixel, std::ldexp(1.0, -obs.level)}),
                               &loss, cameras[obs.keyframe].data(), points[obs.point].data());
    auto ordering = std::make_shared<ceres::ParameterBlockOrdering>();
    for (auto& p : points) ordering->AddElementToGroup(p.data(), 0);
    for (std::size_t i = 0; i < cameras.size(); ++i) {
      ordering->AddElementToGroup(cameras[i].data(), 1);
      if (input.keyframes[i].fixed) problem.SetParameterBlockConstant(cameras[i].data());
    }
    // (No scale anchor: the textbook parameterisation has no such manifold;
    // one block more or less changes nothing measurable.)
    ceres::Solver::Options options;
    options.linear_solver_type = solver;
    options.linear_solver_ordering = ordering;
    options.max_num_iterations = kIterations;
    options.function_tolerance = 0.0;
    options.gradient_tolerance = 0.0;
    options.parameter_tolerance = 0.0;
    options.num_threads = threads;
    options.logging_type = ceres::SILENT;
    ceres::Solver::Summary summary;
    ceres::Solve(options, &problem, &summary);
    iterations = static_cast<int>(summary.iterations.size()) - 1;
    benchmark::DoNotOptimize(points.data());
  }
  report(state, input);
  state.counters["iterations"] = iterations;
}

// ---- one residual with its Jacobians ----------------------------------------

// Residual + Jacobian evaluation of every observation of the local problem,
// the auto-diff work of one iteration.
void BM_ResidualJacobians(benchmark::State& state) {
  const BaProblem& input = local_problem();
  const PinholeRadTan& model = std::get<PinholeRadTan>(camera().model());
  std::vector<std::unique_ptr<ceres::CostFunction>> costs;
  for (const BaObservation& obs : input.observations)
    costs.emplace_back(new ceres::AutoDiffCostFunction<ReprojectionCost<PinholeRadTan>, 2, kSe3ParamSize, 3>(
        new ReprojectionCost<PinholeRadTan>(model, obs.pixel, obs.level)));
  std::vector<std::array<double, kSe3ParamSize>> poses(input.keyframes.size());
  for (std::size_t i = 0; i < poses.size(); ++i) se3_to_params(input.keyframes[i].T_c_w, poses[i].data());
  double residual[2], d_pose[2 * kSe3ParamSize], d_point[6];
  double* jacobians[] = {d_pose, d_point};
  for (auto _ : state) {
    for (std::size_t k = 0; k < costs.size(); ++k) {
      const BaObservation& obs = input.observations[k];
      const double* parameters[] = {poses[obs.keyframe].data(), input.points[obs.point].p_w.data()};
      costs[k]->Evaluate(parameters, residual, jacobians);
      benchmark::DoNotOptimize(d_point[0]);
    }
  }
  state.counters["obs"] = static_cast<double>(costs.size());
}
BENCHMARK(BM_ResidualJacobians)->Unit(benchmark::kMillisecond);

// ---- local BA ----------------------------------------------------------------

void BM_LocalBa(benchmark::State& state) {
  run_ours(state, local_problem(), fixed_iterations(BaLinearSolver::automatic, 1));
}
BENCHMARK(BM_LocalBa)->Unit(benchmark::kMillisecond);

// How local BA grows: args = free neighbours, points in the street.
void BM_LocalBaSize(benchmark::State& state) {
  run_ours(state, local_problem(static_cast<int>(state.range(0)), static_cast<int>(state.range(1))),
           fixed_iterations(BaLinearSolver::automatic, 1));
}
BENCHMARK(BM_LocalBaSize)->Unit(benchmark::kMillisecond)->ArgsProduct({{2, 4, 8}, {1350, 2700, 5400}});

void BM_LocalBaTextbook(benchmark::State& state) { run_textbook(state, local_problem(), ceres::DENSE_SCHUR, 1); }
BENCHMARK(BM_LocalBaTextbook)->Unit(benchmark::kMillisecond);

void BM_LocalBaSparseSchur(benchmark::State& state) {
  run_ours(state, local_problem(), fixed_iterations(BaLinearSolver::sparse_schur, 1));
}
BENCHMARK(BM_LocalBaSparseSchur)->Unit(benchmark::kMillisecond);

// ---- global BA: args = keyframes, solver (0 dense, 1 sparse), threads --------

BaLinearSolver solver_arg(std::int64_t arg) {
  return arg == 0 ? BaLinearSolver::dense_schur : BaLinearSolver::sparse_schur;
}

void BM_GlobalBa(benchmark::State& state) {
  run_ours(state, global_problem(static_cast<int>(state.range(0))),
           fixed_iterations(solver_arg(state.range(1)), static_cast<int>(state.range(2))));
}
BENCHMARK(BM_GlobalBa)
    ->ArgNames({"kf", "sparse", "threads"})
    ->ArgsProduct({{20, 50, 100}, {0, 1}, {1}})
    ->Args({100, 1, 2})
    ->Unit(benchmark::kMillisecond);

void BM_GlobalBaTextbook(benchmark::State& state) {
  run_textbook(state, global_problem(static_cast<int>(state.range(0))),
               state.range(1) == 0 ? ceres::DENSE_SCHUR : ceres::SPARSE_SCHUR, static_cast<int>(state.range(2)));
}
BENCHMARK(BM_GlobalBaTextbook)
    ->ArgNames({"kf", "sparse", "threads"})
    ->ArgsProduct({{20, 50, 100}, {0, 1}, {1}})
    ->Args({100, 1, 2})
    ->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
