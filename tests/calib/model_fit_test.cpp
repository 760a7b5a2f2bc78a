// The model fits on exact and noisy corner projections (no images): the
// templated ATAN projection, the start values, and that both fits recover
// the camera that produced the corners.
#include <cmath>
#include <string>
#include <vector>

#include <ceres/jet.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "calib/atan_calibration.hpp"
#include "calib/atan_projection.hpp"
#include "calib/calibration_result.hpp"
#include "calib/pinhole_calibration.hpp"
#include "core/util/error.hpp"
#include "tests/calib/calib_test_scenes.hpp"

namespace facadeslam::calib {
namespace {

using ::testing::HasSubstr;

const std::vector<Eigen::Vector3d> kPoints = {
    {0.0, 0.0, 1.0}, {0.3, -0.2, 1.5}, {-0.9, 0.6, 1.1}, {1e-9, 2e-9, 1.0}, {1.2, 1.1, 0.8}};

TEST(AtanProjection, AgreesWithCoreAtanCamera) {
  for (double w : {0.0, 1e-6, 0.3, 0.9, 2.0}) {
    const AtanCamera camera{.fx = 410.0, .fy = 405.0, .cx = 318.0, .cy = 242.0, .w = w};
    const double intrinsics[kAtanIntrinsicCount] = {camera.fx, camera.fy, camera.cx, camera.cy, camera.w};
    for (const Eigen::Vector3d& p : kPoints) {
      const Eigen::Vector2d ours = atan_project(intrinsics, p, false);
      const Eigen::Vector2d core = camera.project(p);
      EXPECT_NEAR((ours - core).norm(), 0.0, 1e-9) << "w " << w << " p " << p.transpose();
    }
  }
}

TEST(AtanProjection, TiedFocalUsesFxForBothAxes) {
  const double intrinsics[kAtanIntrinsicCount] = {400.0, 999.0, 320.0, 240.0, 0.5};
  const double tied[kAtanIntrinsicCount] = {400.0, 400.0, 320.0, 240.0, 0.5};
  const Eigen::Vector3d p(0.2, -0.3, 1.0);
  EXPECT_EQ(atan_project(intrinsics, p, true), atan_project(tied, p, false));
  EXPECT_NE(atan_project(intrinsics, p, false), atan_project(tied, p, false));
}

// d pixel / d w by auto-differentiation against a central difference,
// including w near 0 where the series branches take over.
TEST(AtanProjection, DerivativeWithRespectToW) {
  using Jet = ceres::Jet<double, 1>;
  for (double w : {1e-5, 0.2, 0.9, 1.7}) {
    const Eigen::Vector3d p(0.4, -0.25, 1.0);
    const Jet intrinsics[kAtanIntrinsicCount] = {Jet(410.0), Jet(405.0), Jet(318.0), Jet(242.0), Jet(w, 0)};
    const Eigen::Matrix<Jet, 2, 1> px = atan_project(intrinsics, Eigen::Matrix<Jet, 3, 1>(p.cast<Jet>()), false);
    const double h = 1e-6;
    double plus[kAtanIntrinsicCount] = {410.0, 405.0, 318.0, 242.0, w + h};
    double minus[kAtanIntrinsicCount] = {410.0, 405.0, 318.0, 242.0, w - h};
    const Eigen::Vector2d numeric = (atan_project(plus, p, false) - atan_project(minus, p, false)) / (2.0 * h);
    EXPECT_NEAR(px(0).v[0], numeric(0), 1e-4 * (1.0 + std::abs(numeric(0)))) << "w " << w;
    EXPECT_NEAR(px(1).v[0], numeric(1), 1e-4 * (1.0 + std::abs(numeric(1)))) << "w " << w;
  }
}

TEST(AtanStart, FromPinholeBarrelDistortion) {
  const PinholeRadTan pinhole{.fx = 500.0, .fy = 490.0, .cx = 320.0, .cy = 240.0, .k1 = -0.27};
  const std::vector<double> start = atan_start_from_pinhole(pinhole, false);
  ASSERT_EQ(start.size(), 5u);
  // k1 = -(2 tan(w/2))^2 / 3.
  const double a = 2.0 * std::tan(0.5 * start[kAtanW]);
  EXPECT_NEAR(-a * a / 3.0, -0.27, 1e-12);
  // The image scale at the centre is kept: fx * 2 tan(w/2) / w = 500.
  EXPECT_NEAR(start[kAtanFx] * a / start[kAtanW], 500.0, 1e-9);
  EXPECT_NEAR(start[kAtanFy] * a / start[kAtanW], 490.0, 1e-9);
  EXPECT_EQ(start[kAtanCx], 320.0);
  EXPECT_EQ(start[kAtanCy], 240.0);
  EXPECT_EQ(atan_start_from_pinhole(pinhole, true)[kAtanFy], atan_start_from_pinhole(pinhole, true)[kAtanFx]);
}

TEST(AtanStart, PincushionStartsSmallButNotAtZero) {
  const PinholeRadTan pinhole{.fx = 500.0, .fy = 500.0, .cx = 320.0, .cy = 240.0, .k1 = 0.1};
  EXPECT_DOUBLE_EQ(atan_start_from_pinhole(pinhole, false)[kAtanW], 0.05);
}

TEST(ModelKind, ParsesTheTwoNames) {
  EXPECT_EQ(parse_model_kind("pinhole"), ModelKind::pinhole);
  EXPECT_EQ(parse_model_kind("atan"), ModelKind::atan);
  EXPECT_EQ(model_kind_name(ModelKind::atan), "atan");
  try {
    parse_model_kind("fisheye");
    FAIL() << "expected an Error";
  } catch (const Error& e) {
    EXPECT_THAT(e.what(), HasSubstr("camera model 'fisheye': expected pinhole"));
  }
}

TEST(EvaluateCalibration, ResidualIsObservedMinusProjected) {
  const Camera camera = test::true_pinhole();
  const auto poses = test::scene_poses(camera);
  std::vector<AcceptedView> views = test::projected_views(camera, {poses[0], poses[1]}, 0.0);
  for (auto& c : views[1].corners) c += cv::Point2f(0.3f, -0.4f);  // 0.5 px off
  const CalibrationResult r = evaluate_calibration(camera, {poses[0], poses[1]}, views, test::test_board());
  ASSERT_EQ(r.residuals.size(), 2u);
  EXPECT_LT(r.view_rms_px[0], 1e-4);
  EXPECT_NEAR(r.view_rms_px[1], 0.5, 1e-4);
  EXPECT_NEAR(r.residuals[1][7].x(), 0.3, 1e-4);
  EXPECT_NEAR(r.residuals[1][7].y(), -0.4, 1e-4);
  EXPECT_NEAR(r.rms_px, std::sqrt(0.25 / 2.0), 1e-4);
  EXPECT_THROW(evaluate_calibration(camera, {poses[0]}, views, test::test_board()), Error);
}

TEST(PinholeFit, RecoversTheCameraFromExactCorners) {
  const Camera truth = test::true_pinhole();
  const auto views = test::projected_views(truth, test::scene_poses(truth), 0.0);
  const CalibrationResult r = calibrate_pinhole(views, {640, 480}, test::test_board());
  EXPECT_NEAR(r.camera.fx(), truth.fx(), 1e-3);
  EXPECT_NEAR(r.camera.fy(), truth.fy(), 1e-3);
  EXPECT_NEAR(r.camera.cx(), truth.cx(), 1e-3);
  EXPECT_NEAR(r.camera.cy(), truth.cy(), 1e-3);
  const auto& m = std::get<PinholeRadTan>(r.camera.model());
  EXPECT_NEAR(m.k1, -0.22, 1e-4);
  EXPECT_NEAR(m.k2, 0.07, 1e-3);
  EXPECT_NEAR(m.p1, 0.0008, 1e-6);
  EXPECT_NEAR(m.p2, -0.0006, 1e-6);
  EXPECT_LT(r.rms_px, 1e-3);  // corners are stored as float
  EXPECT_EQ(r.T_c_b.size(), views.size());
  EXPECT_LT((r.T_c_b[3].translation() - test::scene_poses(truth)[3].translation()).norm(), 1e-5);
}

TEST(PinholeFit, TooFewViews) {
  const Camera truth = test::true_pinhole();
  const auto poses = test::scene_poses(truth);
  const auto views = test::projected_views(truth, {poses[0], poses[1]}, 0.0);
  EXPECT_THROW(calibrate_pinhole(views, {640, 480}, test::test_board()), Error);
}

TEST(AtanFit, RecoversTheCameraFromExactCorners) {
  const Camera truth = test::true_atan();
  const auto views = test::projected_views(truth, test::scene_poses(truth), 0.0);
  const CalibrationResult start = calibrate_pinhole(views, {640, 480}, test::test_board());
  const CalibrationResult r = calibrate_atan(views, start, test::test_board());
  const auto& m = std::get<AtanCamera>(r.camera.model());
  EXPECT_NEAR(m.fx, 410.0, 1e-3);
  EXPECT_NEAR(m.fy, 408.0, 1e-3);
  EXPECT_NEAR(m.cx, 318.0, 1e-3);
  EXPECT_NEAR(m.cy, 242.0, 1e-3);
  EXPECT_NEAR(m.w, 0.9, 1e-6);
  EXPECT_LT(r.rms_px, 1e-3);
  EXPECT_LT(r.rms_px, start.rms_px);
  EXPECT_LT((r.T_c_b[5].translation() - test::scene_poses(truth)[5].translation()).norm(), 1e-5);
}

TEST(AtanFit, NoisyCornersStillGiveTheCameraClosely) {
  const Camera truth = test::true_atan();
  const auto views = test::projected_views(truth, test::scene_poses(truth), 0.1);
  const CalibrationResult r =
      calibrate_atan(views, calibrate_pinhole(views, {640, 480}, test::test_board()), test::test_board());
  EXPECT_NEAR(r.camera.fx(), 410.0, 0.005 * 410.0);
  EXPECT_NEAR(r.camera.fy(), 408.0, 0.005 * 408.0);
  EXPECT_NEAR(std::get<AtanCamera>(r.camera.model()).w, 0.9, 0.01);
  EXPECT_NEAR(r.rms_px, 0.1 * std::sqrt(2.0), 0.02);  // the noise is per coordinate
}

TEST(AtanFit, FixedAspectTiesTheFocalLengths) {
  const Camera truth(640, 480, AtanCamera{.fx = 400.0, .fy = 400.0, .cx = 322.0, .cy = 236.0, .w = 0.7});
  const auto views = test::projected_views(truth, test::scene_poses(truth), 0.0);
  FitOptions options;
  options.fix_aspect = true;
  const CalibrationResult start = calibrate_pinhole(views, {640, 480}, test::test_board(), options);
  const CalibrationResult r = calibrate_atan(views, start, test::test_board(), options);
  EXPECT_EQ(r.camera.fx(), r.camera.fy());
  EXPECT_NEAR(r.camera.fx(), 400.0, 1e-3);
  EXPECT_NEAR(std::get<AtanCamera>(r.camera.model()).w, 0.7, 1e-6);
}

TEST(AtanFit, NeedsAPinholeStart) {
  const Camera truth = test::true_atan();
  const auto poses = test::scene_poses(truth);
  const auto views = test::projected_views(truth, poses, 0.0);
  const CalibrationResult not_pinhole = evaluate_calibration(truth, poses, views, test::test_board());
  EXPECT_THROW(calibrate_atan(views, not_pinhole, test::test_board()), Error);
}

}  // namespace
}  // namespace facadeslam::calib
