// Bundle adjustment on synthetic street scenes with known truth: recovery
// from perturbed starts, noise, gross outliers, both camera models, fixed
// blocks, abort, points behind the camera, determinism.
#include "mapmaker/ba/bundle_adjuster.hpp"

#include <atomic>
#include <cmath>
#include <iomanip>
#include <set>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "tests/support/synthetic_street.hpp"
#include "tests/mapmaker/ba/ba_test_utils.hpp"

namespace facadeslam {
namespace {

using test::fix_gauge_with_anchor;
using test::pose_errors;

// A figure for the test report (std::to_string would print 1e-9 as 0.000000).
std::string figure(double value) {
  std::ostringstream out;
  out << std::setprecision(4) << value;
  return out.str();
}

// Tolerances tight enough to drive exact data to round-off.
BundleAdjusterOptions exact_options() {
  BundleAdjusterOptions options;
  options.max_iterations = 100;
  options.function_tolerance = 1e-16;
  options.gradient_tolerance = 1e-16;
  options.parameter_tolerance = 1e-14;
  return options;
}

StreetScene street(const Camera& camera, int levels = 1, unsigned seed = 7) {
  StreetSceneOptions options;
  options.keyframes = 10;
  options.points = 1500;
  options.levels = levels;
  options.seed = seed;
  StreetScene scene = make_street_scene(options, camera);
  scene.problem.keyframes[0].fixed = true;  // the gauge, before any perturbation
  return scene;
}

// The pixel RMS of the measurements at the true poses and points.
double rms_at_truth(const StreetScene& scene, const BaProblem& measured, const Camera& camera) {
  BaProblem truth = measured;
  for (std::size_t i = 0; i < truth.keyframes.size(); ++i) truth.keyframes[i].T_c_w = scene.true_T_c_w[i];
  for (std::size_t i = 0; i < truth.points.size(); ++i) truth.points[i].p_w = scene.true_p_w[i];
  for (BaKeyFrame& kf : truth.keyframes) kf.fixed = true;
  for (BaPoint& p : truth.points) p.fixed = true;
  truth.scale_anchor.reset();
  return BundleAdjuster().solve(truth, camera).final_rms_px;
}

void expect_exact_recovery(const Camera& camera) {
  StreetScene scene = street(camera, /*levels=*/4);
  BaProblem& problem = scene.problem;
  ASSERT_GT(problem.points.size(), 1000u);
  perturb_free_blocks(problem, 0.05, 0.1, 0.1, 11);
  fix_gauge_with_anchor(problem, scene.true_T_c_w);

  const BaResult result = BundleAdjuster(exact_options()).solve(problem, camera);
  ::testing::Test::RecordProperty("initial_rms_px", figure(result.initial_rms_px));
  ::testing::Test::RecordProperty("final_rms_px", figure(result.final_rms_px));
  ::testing::Test::RecordProperty("iterations", figure(result.iterations));
  EXPECT_GT(result.initial_rms_px, 10.0);  // the start really is off
  EXPECT_LT(result.final_rms_px, 1e-6);
  EXPECT_FALSE(result.aborted);
  EXPECT_TRUE(result.outliers.empty());
  const test::PoseErrors errors = pose_errors(problem, scene.true_T_c_w);
  ::testing::Test::RecordProperty("max_rotation_error_rad", figure(errors.max_rotation));
  ::testing::Test::RecordProperty("max_centre_error_m", figure(errors.max_centre));
  EXPECT_LT(errors.max_rotation, 1e-8);
  EXPECT_LT(errors.max_centre, 1e-7);
  EXPECT_LT(test::max_point_error(problem, scene.true_p_w), 1e-6);
  EXPECT_EQ(result.free_keyframes, problem.keyframes.size() - 1);
  EXPECT_EQ(result.free_points, problem.points.size());
}

TEST(BundleAdjuster, RecoversTruthFromPerturbedStartPinhole) { expect_exact_recovery(test::pinhole_camera()); }

TEST(BundleAdjuster, RecoversTruthFromPerturbedStartAtan) { expect_exact_recovery(test::atan_camera()); }

TEST(BundleAdjuster, BothSchurSolversAgree) {
  const Camera camera = test::pinhole_camera();
  StreetScene scene = street(camera);
  add_pixel_noise(scene.problem, 0.5, 3);
  perturb_free_blocks(scene.problem, 0.02, 0.05, 0.05, 4);
  fix_gauge_with_anchor(scene.problem, scene.true_T_c_w);
  BaProblem dense = scene.problem;
  BaProblem sparse = scene.problem;
  BundleAdjusterOptions options = exact_options();
  options.solver = BaLinearSolver::dense_schur;
  BundleAdjuster(options).solve(dense, camera);
  options.solver = BaLinearSolver::sparse_schur;
  BundleAdjuster(options).solve(sparse, camera);
  const test::PoseErrors diff = pose_errors(dense, test::poses_of(sparse));
  EXPECT_LT(diff.max_rotation, 1e-9);
  EXPECT_LT(diff.max_centre, 1e-8);
}

TEST(BundleAdjuster, NoisyObservationsGiveTheExpectedResidual) {
  const Camera camera = test::pinhole_camera();
  StreetScene scene = street(camera);
  BaProblem& problem = scene.problem;
  constexpr double kSigma = 0.5;  // per axis, level 0
  add_pixel_noise(problem, kSigma, 21);
  perturb_free_blocks(problem, 0.05, 0.1, 0.1, 22);
  fix_gauge_with_anchor(problem, scene.true_T_c_w);
  const double truth_rms = rms_at_truth(scene, problem, camera);

  BundleAdjusterOptions options;
  options.loss = BaLoss::none;  // plain least squares: the ML estimate under Gaussian noise
  const BaResult result = BundleAdjuster(options).solve(problem, camera);
  // E|e|^2 = 2 sigma^2 per observation, less the degrees of freedom fitted:
  // 6 per free keyframe (5 for the anchored one), 3 per point.
  const double m = 2.0 * static_cast<double>(problem.observations.size());
  const double free_keyframes = static_cast<double>(problem.keyframes.size()) - 2.0;
  const double p = 6.0 * free_keyframes + 5.0 + 3.0 * static_cast<double>(problem.points.size());
  const double expected = kSigma * std::sqrt(2.0) * std::sqrt((m - p) / m);
  ::testing::Test::RecordProperty("final_rms_px", figure(result.final_rms_px));
  ::testing::Test::RecordProperty("expected_rms_px", figure(expected));
  EXPECT_TRUE(result.converged);
  EXPECT_NEAR(result.final_rms_px, expected, 0.05 * expected);
  // The estimate fits the data at least as well as the truth does.
  EXPECT_LE(result.final_rms_px, truth_rms);
  const test::PoseErrors errors = pose_errors(problem, scene.true_T_c_w);
  ::testing::Test::RecordProperty("max_rotation_error_rad", figure(errors.max_rotation));
  ::testing::Test::RecordProperty("max_centre_error_m", figure(errors.max_centre));
  // A facade is nearly planar (+-0.5 m relief at 8 m), which leaves a weak
  // rotation/translation direction: ~1 mrad and ~1 cm at 0.5 px here.
  EXPECT_LT(errors.max_rotation, 2e-3);
  EXPECT_LT(errors.max_centre, 0.02);
  // Half-pixel noise is far inside the chi-square bound at sigma = 1 px.
  EXPECT_TRUE(result.outliers.empty());
}

struct OutlierCase {
  BaLoss loss;
  double loss_scale;
  double start_rotation;  // perturbation of the start
  double start_translation;
  double start_point;
  double max_error_ratio;  // allowed pose error with outliers / without
};

class RobustLossTest : public ::testing::TestWithParam<OutlierCase> {
 protected:
  // Solves the street scene with 0.5 px noise, with or without 5 % gross
  // outliers (20 px), from the perturbed start of the case.
  BaResult solve(bool with_outliers, std::vector<std::size_t>* injected, test::PoseErrors* errors, BaLoss loss) const {
    const Camera camera = test::pinhole_camera();
    StreetScene scene = street(camera);
    add_pixel_noise(scene.problem, 0.5, 31);
    if (with_outliers) *injected = add_gross_outliers(scene.problem, 0.05, 20.0, 33);
    const OutlierCase& c = GetParam();
    perturb_free_blocks(scene.problem, c.start_rotation, c.start_translation, c.start_point, 32);
    fix_gauge_with_anchor(scene.problem, scene.true_T_c_w);
    BundleAdjusterOptions options;
    options.loss = loss;
    options.loss_scale = c.loss_scale;
    options.max_iterations = 50;
    const BaResult result = BundleAdjuster(options).solve(scene.problem, camera);
    *errors = pose_errors(scene.problem, scene.true_T_c_w);
    return result;
  }
};

TEST_P(RobustLossTest, GrossOutliersAreDownWeightedAndReported) {
  std::vector<std::size_t> injected;
  test::PoseErrors clean, dirty, plain;
  solve(false, &injected, &clean, GetParam().loss);
  const BaResult result = solve(true, &injected, &dirty, GetParam().loss);
  solve(true, &injected, &plain, BaLoss::none);  // the control: least squares

  ::testing::Test::RecordProperty("clean_max_centre_m", figure(clean.max_centre));
  ::testing::Test::RecordProperty("outliers_max_centre_m", figure(dirty.max_centre));
  ::testing::Test::RecordProperty("outliers_max_rotation_rad", figure(dirty.max_rotation));
  ::testing::Test::RecordProperty("least_squares_max_centre_m", figure(plain.max_centre));
  // About as accurate as without the outliers (the noise alone leaves ~1 cm) ...
  const double ratio = GetParam().max_error_ratio;
  EXPECT_LT(dirty.max_rotation, ratio * clean.max_rotation + 2e-4);
  EXPECT_LT(dirty.max_centre, ratio * clean.max_centre + 2e-3);
  // ... where plain least squares is thrown off by them.
  EXPECT_GT(plain.max_centre, 3.0 * dirty.max_centre);

  // The injected outliers are reported, and few others: an outlier on a
  // point seen only twice can be shared between its two observations.
  const std::set<std::size_t> reported(result.outliers.begin(), result.outliers.end());
  std::size_t found = 0;
  for (std::size_t i : injected) found += reported.count(i);
  ::testing::Test::RecordProperty("injected", figure(injected.size()));
  ::testing::Test::RecordProperty("found", figure(found));
  ::testing::Test::RecordProperty("false_alarms", figure(reported.size() - found));
  EXPECT_GE(static_cast<double>(found), 0.97 * static_cast<double>(injected.size()));
  EXPECT_LE(static_cast<double>(reported.size() - found), 0.1 * static_cast<double>(injected.size()));
  EXPECT_LT(result.final_inlier_rms_px, 0.75);  // the inliers' 0.5 px x sqrt(2), less the fit
}

INSTANTIATE_TEST_SUITE_P(Losses, RobustLossTest,
                         ::testing::Values(OutlierCase{BaLoss::cauchy, 2.447651, 0.05, 0.1, 0.05, 1.5},
                                           // Huber's influence is bounded but never falls
                                           // off: the outliers still pull a little.
                                           OutlierCase{BaLoss::huber, 2.447651, 0.05, 0.1, 0.05, 2.5},
                                           // Tukey ignores everything beyond its scale, so it
                                           // needs a start within a pixel or so.
                                           OutlierCase{BaLoss::tukey, 4.685, 0.001, 0.002, 0.002, 1.5}),
                         [](const auto& info) {
                           switch (info.param.loss) {
                             case BaLoss::cauchy: return std::string("cauchy");
                             case BaLoss::huber: return std::string("huber");
                             case BaLoss::tukey: return std::string("tukey");
                             default: return std::string("none");
                           }
                         });

// A fifth of the points move (they sink faster and faster, as nothing on a
// facade does) and pull the poses under plain least squares; with their
// observations weighed down (label-aware bundle adjustment) the poses come
// out about as well as when those points stand still.
TEST(BundleAdjuster, DownWeightedObservationsPullThePosesLess) {
  const Camera camera = test::pinhole_camera();
  auto solve = [&](bool moving, double weight) {
    StreetScene scene = street(camera);
    for (BaObservation& obs : scene.problem.observations) {
      if (obs.point % 5 != 0) continue;
      const double k = static_cast<double>(obs.keyframe);
      const Eigen::Vector3d p_w = scene.true_p_w[obs.point] + Eigen::Vector3d(0.0, moving ? 0.005 * k * k : 0.0, 0.0);
      obs.pixel = camera.project(scene.true_T_c_w[obs.keyframe] * p_w);
      obs.weight = weight;
    }
    add_pixel_noise(scene.problem, 0.5, 61);
    perturb_free_blocks(scene.problem, 0.01, 0.02, 0.02, 62);
    fix_gauge_with_anchor(scene.problem, scene.true_T_c_w);
    BundleAdjusterOptions options;
    options.loss = BaLoss::none;
    options.max_iterations = 50;
    BundleAdjuster(options).solve(scene.problem, camera);
    return pose_errors(scene.problem, scene.true_T_c_w).max_centre;
  };
  const double still = solve(false, 1.0);
  const double pulled = solve(true, 1.0);
  const double weighted = solve(true, 0.01);
  ::testing::Test::RecordProperty("still_max_centre_m", figure(still));
  ::testing::Test::RecordProperty("moving_max_centre_m", figure(pulled));
  ::testing::Test::RecordProperty("moving_weighted_max_centre_m", figure(weighted));
  EXPECT_GT(pulled, 3.0 * still);           // the moving points do pull at full weight ...
  EXPECT_LT(weighted, 1.5 * still + 2e-3);  // ... and hardly at all weighed down
}

TEST(BundleAdjuster, FixedBlocksDoNotMove) {
  const Camera camera = test::pinhole_camera();
  StreetScene scene = street(camera);
  BaProblem& problem = scene.problem;
  add_pixel_noise(problem, 0.5, 41);
  perturb_free_blocks(problem, 0.02, 0.05, 0.05, 42);
  problem.keyframes[0].fixed = true;
  problem.keyframes[3].fixed = true;
  for (std::size_t i = 0; i < problem.points.size(); i += 10) problem.points[i].fixed = true;
  // An extra keyframe and point that nothing observes are left alone too.
  problem.keyframes.push_back({99, SE3d::exp(SE3d::Tangent::Constant(0.3)), false});
  problem.points.push_back({999, Eigen::Vector3d(1, 2, 3), false});
  const BaProblem before = problem;

  const BaResult result = BundleAdjuster().solve(problem, camera);
  EXPECT_LT(result.final_rms_px, result.initial_rms_px);
  for (std::size_t i : {std::size_t{0}, std::size_t{3}, problem.keyframes.size() - 1}) {
    EXPECT_EQ(problem.keyframes[i].T_c_w.unit_quaternion().coeffs(),
              before.keyframes[i].T_c_w.unit_quaternion().coeffs());
    EXPECT_EQ(problem.keyframes[i].T_c_w.translation(), before.keyframes[i].T_c_w.translation());
  }
  for (std::size_t i = 0; i + 1 < problem.points.size(); i += 10)
    EXPECT_EQ(problem.points[i].p_w, before.points[i].p_w);
  EXPECT_EQ(problem.points.back().p_w, before.points.back().p_w);
  // ... while the free ones did move.
  EXPECT_NE(problem.keyframes[1].T_c_w.translation(), before.keyframes[1].T_c_w.translation());
  EXPECT_NE(problem.points[1].p_w, before.points[1].p_w);
  EXPECT_EQ(result.free_keyframes, 8u);  // 10 observed keyframes, 0 and 3 fixed
}

TEST(BundleAdjuster, ScaleAnchorKeepsTheDistance) {
  const Camera camera = test::pinhole_camera();
  StreetScene scene = street(camera);
  BaProblem& problem = scene.problem;
  add_pixel_noise(problem, 0.5, 51);
  perturb_free_blocks(problem, 0.02, 0.05, 0.05, 52);
  problem.keyframes[0].fixed = true;
  problem.scale_anchor = BaScaleAnchor{3, 0};
  const double before = test::centre_error(problem.keyframes[3].T_c_w, problem.keyframes[0].T_c_w);
  const SE3d start = problem.keyframes[3].T_c_w;
  BundleAdjuster().solve(problem, camera);
  EXPECT_NEAR(test::centre_error(problem.keyframes[3].T_c_w, problem.keyframes[0].T_c_w), before, 1e-9 * before);
  // The anchored keyframe still moves (its rotation and direction are free).
  EXPECT_GT(test::rotation_error(problem.keyframes[3].T_c_w, start), 1e-3);
}

TEST(BundleAdjuster, AbortFlagSetBeforeTheSolveReturnsAtOnce) {
  const Camera camera = test::pinhole_camera();
  StreetScene scene = street(camera);
  perturb_free_blocks(scene.problem, 0.02, 0.05, 0.05, 61);
  scene.problem.keyframes[0].fixed = true;
  const BaProblem before = scene.problem;
  std::atomic<bool> abort{true};
  BundleAdjusterOptions options;
  options.abort = &abort;
  const BaResult result = BundleAdjuster(options).solve(scene.problem, camera);
  EXPECT_TRUE(result.aborted);
  EXPECT_FALSE(result.converged);
  EXPECT_EQ(result.iterations, 0);
  EXPECT_EQ(result.final_rms_px, result.initial_rms_px);
  for (std::size_t i = 0; i < before.points.size(); ++i) EXPECT_EQ(scene.problem.points[i].p_w, before.points[i].p_w);
}

TEST(BundleAdjuster, AbortFlagSetDuringTheSolveStopsItAndKeepsProgress) {
  const Camera camera = test::pinhole_camera();
  StreetScene scene = street(camera);
  add_pixel_noise(scene.problem, 0.5, 71);
  perturb_free_blocks(scene.problem, 0.05, 0.1, 0.1, 72);
  scene.problem.keyframes[0].fixed = true;
  BaProblem full = scene.problem;

  std::atomic<bool> abort{false};
  BundleAdjusterOptions options = exact_options();
  options.abort = &abort;
  options.on_iteration = [&](int iteration) {
    if (iteration == 2) abort.store(true);  // as the map maker would when a keyframe arrives
  };
  const BaResult aborted = BundleAdjuster(options).solve(scene.problem, camera);
  EXPECT_TRUE(aborted.aborted);
  EXPECT_FALSE(aborted.converged);
  EXPECT_EQ(aborted.iterations, 2);
  EXPECT_LT(aborted.final_rms_px, aborted.initial_rms_px);  // the two iterations were kept

  options.abort = nullptr;
  options.on_iteration = nullptr;
  const BaResult complete = BundleAdjuster(options).solve(full, camera);
  EXPECT_FALSE(complete.aborted);
  EXPECT_GT(complete.iterations, 2);
  EXPECT_LT(complete.final_rms_px, aborted.final_rms_px);
}

TEST(BundleAdjuster, PointsBehindACameraStayFiniteAndAreReported) {
  const Camera camera = test::pinhole_camera();
  StreetScene scene = street(camera);
  BaProblem& problem = scene.problem;
  problem.keyframes[0].fixed = true;
  const SE3d T_w_c2 = problem.keyframes[2].T_c_w.inverse();

  // A (fixed) point 3 m behind keyframe 2 which keyframe 2 claims to see at
  // the image centre: a wrong association.
  problem.points.push_back({5000, T_w_c2 * Eigen::Vector3d(0.2, 0.1, -3.0), true});
  const std::size_t wrong = problem.observations.size();
  problem.observations.push_back({2, problem.points.size() - 1, Eigen::Vector2d(319.5, 239.5), 0});
  // A free point truly 6 m in front of keyframe 2, seen correctly by
  // keyframes 2, 3 and 4, whose estimate starts behind them all.
  const Eigen::Vector3d truth = T_w_c2 * Eigen::Vector3d(0.3, -0.2, 6.0);
  problem.points.push_back({5001, T_w_c2 * Eigen::Vector3d(0.3, -0.2, -6.0), false});
  for (std::size_t k : {std::size_t{2}, std::size_t{3}, std::size_t{4}})
    problem.observations.push_back(
        {k, problem.points.size() - 1, camera.project(problem.keyframes[k].T_c_w * truth), 0});

  test::fix_gauge_with_anchor(problem, scene.true_T_c_w);  // else the outliers could pull the free scale
  const BaResult result = BundleAdjuster().solve(problem, camera);
  EXPECT_TRUE(std::isfinite(result.initial_rms_px));
  EXPECT_TRUE(std::isfinite(result.final_rms_px));
  for (const BaKeyFrame& kf : problem.keyframes) {
    EXPECT_TRUE(kf.T_c_w.translation().allFinite());
    EXPECT_TRUE(kf.T_c_w.unit_quaternion().coeffs().allFinite());
  }
  for (const BaPoint& point : problem.points) EXPECT_TRUE(point.p_w.allFinite());
  const std::set<std::size_t> reported(result.outliers.begin(), result.outliers.end());
  EXPECT_TRUE(reported.contains(wrong));
  // The rest of the map is unharmed: the cameras stay at the truth.
  EXPECT_LT(pose_errors(problem, scene.true_T_c_w).max_centre, 1e-3);
}

TEST(BundleAdjuster, SingleThreadedSolvesAreBitIdentical) {
  const Camera camera = test::pinhole_camera();
  StreetScene scene = street(camera, 4);
  add_pixel_noise(scene.problem, 0.7, 81);
  add_gross_outliers(scene.problem, 0.03, 15.0, 82);
  perturb_free_blocks(scene.problem, 0.03, 0.05, 0.05, 83);
  fix_gauge_with_anchor(scene.problem, scene.true_T_c_w);
  BaProblem a = scene.problem;
  BaProblem b = scene.problem;
  const BaResult ra = BundleAdjuster().solve(a, camera);
  const BaResult rb = BundleAdjuster().solve(b, camera);
  EXPECT_EQ(ra.iterations, rb.iterations);
  EXPECT_EQ(ra.final_rms_px, rb.final_rms_px);
  EXPECT_EQ(ra.outliers, rb.outliers);
  for (std::size_t i = 0; i < a.keyframes.size(); ++i) {
    EXPECT_EQ(a.keyframes[i].T_c_w.unit_quaternion().coeffs(), b.keyframes[i].T_c_w.unit_quaternion().coeffs());
    EXPECT_EQ(a.keyframes[i].T_c_w.translation(), b.keyframes[i].T_c_w.translation());
  }
  for (std::size_t i = 0; i < a.points.size(); ++i) EXPECT_EQ(a.points[i].p_w, b.points[i].p_w);
}

TEST(BundleAdjuster, TwoThreadsAgreeWithOneToRoundOff) {
  // Multi-threaded Ceres is not bit-reproducible (summation order), but it
  // solves the same problem.
  const Camera camera = test::pinhole_camera();
  StreetScene scene = street(camera);
  add_pixel_noise(scene.problem, 0.5, 91);
  perturb_free_blocks(scene.problem, 0.03, 0.05, 0.05, 92);
  fix_gauge_with_anchor(scene.problem, scene.true_T_c_w);
  BaProblem one = scene.problem;
  BaProblem two = scene.problem;
  BundleAdjusterOptions options = exact_options();
  BundleAdjuster(options).solve(one, camera);
  options.num_threads = 2;
  BundleAdjuster(options).solve(two, camera);
  const test::PoseErrors diff = pose_errors(two, test::poses_of(one));
  EXPECT_LT(diff.max_rotation, 1e-9);
  EXPECT_LT(diff.max_centre, 1e-8);
}

TEST(BundleAdjuster, NothingFreeMeansNothingChanges) {
  const Camera camera = test::pinhole_camera();
  StreetScene scene = street(camera);
  add_pixel_noise(scene.problem, 0.5, 95);
  for (BaKeyFrame& kf : scene.problem.keyframes) kf.fixed = true;
  for (BaPoint& p : scene.problem.points) p.fixed = true;
  const BaProblem before = scene.problem;
  const BaResult result = BundleAdjuster().solve(scene.problem, camera);
  EXPECT_TRUE(result.converged);
  EXPECT_EQ(result.iterations, 0);
  EXPECT_EQ(result.free_keyframes, 0u);
  EXPECT_EQ(result.free_points, 0u);
  EXPECT_EQ(result.final_rms_px, result.initial_rms_px);
  EXPECT_GT(result.final_rms_px, 0.3);  // the noise is still there
  for (std::size_t i = 0; i < before.points.size(); ++i) EXPECT_EQ(scene.problem.points[i].p_w, before.points[i].p_w);

  BaProblem empty;
  const BaResult none = BundleAdjuster().solve(empty, camera);
  EXPECT_TRUE(none.converged);
  EXPECT_EQ(none.final_rms_px, 0.0);
}

TEST(BundleAdjuster, PoseOnlyProblemUsesFixedPoints) {
  // Every point fixed, keyframes free: pose refinement, no Schur elimination.
  const Camera camera = test::pinhole_camera();
  StreetScene scene = street(camera);
  for (BaPoint& p : scene.problem.points) p.fixed = true;
  perturb_free_blocks(scene.problem, 0.03, 0.05, 0.0, 96);
  const BaResult result = BundleAdjuster(exact_options()).solve(scene.problem, camera);
  EXPECT_EQ(result.free_points, 0u);
  EXPECT_LT(result.final_rms_px, 1e-6);
  EXPECT_LT(pose_errors(scene.problem, scene.true_T_c_w).max_centre, 1e-8);
}

}  // namespace
}  // namespace facadeslam
