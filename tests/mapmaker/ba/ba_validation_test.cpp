// Bad problems and bad options: one test per case, each a clear Error.
#include <limits>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "core/util/error.hpp"
#include "mapmaker/ba/bundle_adjuster.hpp"
#include "tests/mapmaker/ba/ba_test_utils.hpp"

namespace facadeslam {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// Two keyframes (the first fixed), two points, four observations: valid.
BaProblem small_problem() {
  BaProblem p;
  p.keyframes = {{0, SE3d(), true}, {1, SE3d(SO3d(), Eigen::Vector3d(-1, 0, 0)), false}};
  p.points = {{0, Eigen::Vector3d(0, 0, 5), false}, {1, Eigen::Vector3d(1, 1, 6), false}};
  const Camera camera = test::pinhole_camera();
  for (std::size_t k = 0; k < 2; ++k)
    for (std::size_t j = 0; j < 2; ++j)
      p.observations.push_back({k, j, camera.project(p.keyframes[k].T_c_w * p.points[j].p_w), 0});
  return p;
}

void expect_rejected(BaProblem problem, const std::string& fragment) {
  try {
    BundleAdjuster().solve(problem, test::pinhole_camera());
    ADD_FAILURE() << "expected an Error mentioning '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr(fragment));
  }
}

TEST(BaProblemValidation, TheSmallProblemIsValid) {
  BaProblem p = small_problem();
  EXPECT_NO_THROW(validate_ba_problem(p));
  EXPECT_LT(BundleAdjuster().solve(p, test::pinhole_camera()).final_rms_px, 1e-9);
}

TEST(BaProblemValidation, KeyframeIndexOutOfRange) {
  BaProblem p = small_problem();
  p.observations[2].keyframe = 2;
  expect_rejected(p, "observation 2 refers to keyframe index 2");
}

TEST(BaProblemValidation, PointIndexOutOfRange) {
  BaProblem p = small_problem();
  p.observations[1].point = 7;
  expect_rejected(p, "observation 1 refers to point index 7");
}

TEST(BaProblemValidation, NonFinitePixel) {
  BaProblem p = small_problem();
  p.observations[0].pixel.y() = kNaN;
  expect_rejected(p, "observation 0 has a non-finite pixel");
}

TEST(BaProblemValidation, NegativeLevel) {
  BaProblem p = small_problem();
  p.observations[3].level = -1;
  expect_rejected(p, "observation 3 has pyramid level -1");
}

TEST(BaProblemValidation, LevelTooHigh) {
  BaProblem p = small_problem();
  p.observations[3].level = kMaxBaLevel + 1;
  expect_rejected(p, "pyramid level 16");
}

TEST(BaProblemValidation, WeightOutsideZeroToOne) {
  for (const double weight : {0.0, -0.5, 1.5, kNaN}) {
    BaProblem p = small_problem();
    p.observations[2].weight = weight;
    expect_rejected(p, "observation 2 has weight");
  }
}

TEST(BaProblemValidation, NonFinitePose) {
  BaProblem p = small_problem();
  p.keyframes[1].T_c_w.translation().x() = kNaN;
  expect_rejected(p, "keyframe 1 (id 1) has a non-finite pose");
}

TEST(BaProblemValidation, NonFinitePoint) {
  BaProblem p = small_problem();
  p.points[1].p_w.z() = std::numeric_limits<double>::infinity();
  expect_rejected(p, "point 1 (id 1) has a non-finite position");
}

TEST(BaProblemValidation, NothingFixed) {
  BaProblem p = small_problem();
  p.keyframes[0].fixed = false;
  expect_rejected(p, "no keyframe or point taking part is fixed");
}

TEST(BaProblemValidation, ScaleAnchorOutOfRange) {
  BaProblem p = small_problem();
  p.scale_anchor = BaScaleAnchor{5, 0};
  expect_rejected(p, "scale anchor names keyframe index 5");
}

TEST(BaProblemValidation, ScaleAnchorOnItself) {
  BaProblem p = small_problem();
  p.scale_anchor = BaScaleAnchor{0, 0};
  expect_rejected(p, "two different keyframes");
}

TEST(BaProblemValidation, ScaleAnchorReferenceFree) {
  BaProblem p = small_problem();
  p.keyframes.push_back({2, SE3d(SO3d(), Eigen::Vector3d(-2, 0, 0)), false});
  p.scale_anchor = BaScaleAnchor{1, 2};
  expect_rejected(p, "reference keyframe (index 2) must be fixed");
}

TEST(BaProblemValidation, ScaleAnchorKeyframeFixed) {
  BaProblem p = small_problem();
  p.keyframes[1].fixed = true;
  p.scale_anchor = BaScaleAnchor{1, 0};
  expect_rejected(p, "keyframe (index 1) must be free");
}

TEST(BaProblemValidation, ScaleAnchorSameCentre) {
  BaProblem p = small_problem();
  p.keyframes[1].T_c_w = SE3d(SO3d::exp(Eigen::Vector3d(0, 0.1, 0)), Eigen::Vector3d::Zero());
  p.scale_anchor = BaScaleAnchor{1, 0};
  expect_rejected(p, "same camera centre");
}

TEST(BaProblemValidation, FailedValidationLeavesTheProblemUntouched) {
  BaProblem p = small_problem();
  p.keyframes[1].T_c_w = SE3d(SO3d(), Eigen::Vector3d(-1.1, 0.1, 0));
  p.observations.back().level = -3;
  const BaProblem before = p;
  EXPECT_THROW(BundleAdjuster().solve(p, test::pinhole_camera()), Error);
  EXPECT_EQ(p.keyframes[1].T_c_w.translation(), before.keyframes[1].T_c_w.translation());
}

void expect_bad_options(const BundleAdjusterOptions& options, const std::string& fragment) {
  try {
    BundleAdjuster adjuster(options);
    ADD_FAILURE() << "expected an Error mentioning '" << fragment << "'";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr(fragment));
  }
}

TEST(BundleAdjusterOptions, DefaultsAreValid) { EXPECT_NO_THROW(BundleAdjuster{}); }

TEST(BundleAdjusterOptions, NegativeIterations) {
  BundleAdjusterOptions o;
  o.max_iterations = -1;
  expect_bad_options(o, "max_iterations");
}

TEST(BundleAdjusterOptions, NonPositiveLossScale) {
  BundleAdjusterOptions o;
  o.loss_scale = 0.0;
  expect_bad_options(o, "loss_scale");
  o.loss_scale = kNaN;
  expect_bad_options(o, "loss_scale");
}

TEST(BundleAdjusterOptions, NonPositiveChi2) {
  BundleAdjusterOptions o;
  o.outlier_chi2 = -5.991;
  expect_bad_options(o, "outlier_chi2");
}

TEST(BundleAdjusterOptions, ZeroThreads) {
  BundleAdjusterOptions o;
  o.num_threads = 0;
  expect_bad_options(o, "num_threads");
}

TEST(BundleAdjusterOptions, NegativeDenseLimit) {
  BundleAdjusterOptions o;
  o.dense_schur_max_free_keyframes = -2;
  expect_bad_options(o, "dense_schur_max_free_keyframes");
}

TEST(BundleAdjusterOptions, BadTolerance) {
  BundleAdjusterOptions o;
  o.function_tolerance = -1e-6;
  expect_bad_options(o, "tolerances");
  o = {};
  o.parameter_tolerance = kNaN;
  expect_bad_options(o, "tolerances");
}

}  // namespace
}  // namespace facadeslam
