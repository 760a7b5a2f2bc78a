// Calibration against ground truth: chessboard images rendered through
// known cameras (tests/calib/synthetic_board.hpp), then calibrated from the
// image files exactly as `facadeslam calibrate` does.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <memory>
#include <string>
#include <vector>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "calib/calibrate.hpp"
#include "core/util/error.hpp"
#include "tests/calib/calib_test_scenes.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::calib {
namespace {

using ::testing::HasSubstr;

using test::rendered_views;
using test::test_board;
using test::true_atan;
using test::true_pinhole;
using test::write_png;
using test::write_views;

CalibrationRequest request_for(const std::filesystem::path& folder, ModelKind model) {
  CalibrationRequest request;
  request.images = folder;
  request.board = test_board();
  request.model = model;
  return request;
}

// Largest pixel discrepancy between the two cameras over the central part
// of the image (where the rendered boards put corners): each pixel's true
// ray is projected with the estimate.
double max_projection_difference(const Camera& truth, const Camera& estimate, double margin_fraction) {
  double worst = 0.0;
  for (int j = 0; j <= 20; ++j)
    for (int i = 0; i <= 20; ++i) {
      const double u = truth.width() * (margin_fraction + (1.0 - 2.0 * margin_fraction) * i / 20.0);
      const double v = truth.height() * (margin_fraction + (1.0 - 2.0 * margin_fraction) * j / 20.0);
      const Eigen::Vector2d px(u, v);
      worst = std::max(worst, (estimate.project(truth.unproject(px)) - px).norm());
    }
  return worst;
}

// The distortion alone: how far apart (in pixels, at the true focal
// length) the two models put the distorted image of the same normalised
// point, over the same central part of the image. Both cameras must use
// the same model.
double max_distortion_difference(const Camera& truth, const Camera& estimate, double margin_fraction) {
  double worst = 0.0;
  for (int j = 0; j <= 20; ++j)
    for (int i = 0; i <= 20; ++i) {
      const double u = truth.width() * (margin_fraction + (1.0 - 2.0 * margin_fraction) * i / 20.0);
      const double v = truth.height() * (margin_fraction + (1.0 - 2.0 * margin_fraction) * j / 20.0);
      const Eigen::Vector2d xn = truth.unproject({u, v}).head<2>();
      const Eigen::Vector2d d_true = truth.visit([&](const auto& m) { return m.distort(xn); });
      const Eigen::Vector2d d_est = estimate.visit([&](const auto& m) { return m.distort(xn); });
      worst = std::max(worst, truth.fx() * (d_true - d_est).norm());
    }
  return worst;
}

void expect_intrinsics_near(const Camera& truth, const Camera& estimate) {
  EXPECT_NEAR(estimate.fx(), truth.fx(), 0.005 * truth.fx());
  EXPECT_NEAR(estimate.fy(), truth.fy(), 0.005 * truth.fy());
  EXPECT_NEAR(estimate.cx(), truth.cx(), 0.005 * truth.width());
  EXPECT_NEAR(estimate.cy(), truth.cy(), 0.005 * truth.width());
}

TEST(SyntheticCalibration, RenderedBoardsAreFoundInEveryView) {
  test::TempDir dir;
  write_views(dir.path(), rendered_views(true_pinhole()), 10);
  const CalibrationRun run = run_calibration(request_for(dir.path(), ModelKind::pinhole));
  EXPECT_EQ(run.views.image_count, 10u);
  EXPECT_EQ(run.views.views.size(), 10u);
  EXPECT_TRUE(run.views.rejected.empty());
  EXPECT_EQ(run.views.image_size, cv::Size(640, 480));
}

TEST(SyntheticCalibration, PinholeRecoversKnownIntrinsicsAndDistortion) {
  test::TempDir dir;
  write_views(dir.path(), rendered_views(true_pinhole()), 10);
  const CalibrationRun run = run_calibration(request_for(dir.path(), ModelKind::pinhole));
  const Camera truth = true_pinhole();
  ASSERT_EQ(run.result.camera.model_name(), "pinhole");
  expect_intrinsics_near(truth, run.result.camera);
  const auto& m = std::get<PinholeRadTan>(run.result.camera.model());
  EXPECT_NEAR(m.k1, -0.22, 0.02);
  EXPECT_NEAR(m.p1, 0.0008, 0.0005);
  EXPECT_NEAR(m.p2, -0.0006, 0.0005);
  EXPECT_LT(max_distortion_difference(truth, run.result.camera, 0.1), 0.3);
  EXPECT_LT(max_projection_difference(truth, run.result.camera, 0.1), 1.0);
  EXPECT_LT(run.result.rms_px, 0.1);
  EXPECT_FALSE(run.pinhole_rms_px.has_value());
}

TEST(SyntheticCalibration, AtanRecoversKnownIntrinsicsAndW) {
  test::TempDir dir;
  write_views(dir.path(), rendered_views(true_atan()), 10);
  const CalibrationRun run = run_calibration(request_for(dir.path(), ModelKind::atan));
  const Camera truth = true_atan();
  ASSERT_EQ(run.result.camera.model_name(), "atan");
  expect_intrinsics_near(truth, run.result.camera);
  EXPECT_NEAR(std::get<AtanCamera>(run.result.camera.model()).w, 0.9, 0.005 * 0.9);
  EXPECT_LT(max_distortion_difference(truth, run.result.camera, 0.1), 0.3);
  EXPECT_LT(max_projection_difference(truth, run.result.camera, 0.1), 1.0);
  EXPECT_LT(run.result.rms_px, 0.1);
  ASSERT_TRUE(run.pinhole_rms_px.has_value());
  EXPECT_GE(*run.pinhole_rms_px, run.result.rms_px);  // the true model fits at least as well
}

TEST(SyntheticCalibration, FixedAspectGivesEqualFocalLengths) {
  test::TempDir dir;
  write_views(dir.path(), rendered_views(true_atan()), 10);
  CalibrationRequest request = request_for(dir.path(), ModelKind::atan);
  request.fit.fix_aspect = true;
  const CalibrationRun atan = run_calibration(request);
  EXPECT_EQ(atan.result.camera.fx(), atan.result.camera.fy());
  request.model = ModelKind::pinhole;
  const CalibrationRun pinhole = run_calibration(request);
  EXPECT_DOUBLE_EQ(pinhole.result.camera.fx(), pinhole.result.camera.fy());
  // The true focal lengths differ by 0.5 %, so tying them costs accuracy.
  EXPECT_GT(atan.result.rms_px, 0.0);
}

TEST(SyntheticCalibration, FixK3KeepsItZero) {
  test::TempDir dir;
  write_views(dir.path(), rendered_views(true_pinhole()), 10);
  CalibrationRequest request = request_for(dir.path(), ModelKind::pinhole);
  request.fit.fix_k3 = true;
  const CalibrationRun run = run_calibration(request);
  EXPECT_EQ(std::get<PinholeRadTan>(run.result.camera.model()).k3, 0.0);
  expect_intrinsics_near(true_pinhole(), run.result.camera);
}

TEST(SyntheticCalibration, RejectsDuplicateBlurredAndUndecodableImages) {
  test::TempDir dir;
  const auto& images = rendered_views(true_pinhole());
  write_views(dir.path(), images, 5);
  write_png(dir / "view_00_again.png", images[0]);  // sorts right after view_00.png
  cv::Mat blurred;
  cv::GaussianBlur(images[1], blurred, cv::Size(0, 0), 3.5);
  write_png(dir / "view_01_blurred.png", blurred);
  test::write_text(dir / "view_02_broken.png", "this is not a PNG");

  const CalibrationRun run = run_calibration(request_for(dir.path(), ModelKind::pinhole));
  EXPECT_EQ(run.views.image_count, 8u);
  EXPECT_EQ(run.views.views.size(), 5u);
  ASSERT_EQ(run.views.rejected.size(), 3u);
  EXPECT_EQ(run.views.rejected[0].file.filename(), "view_00_again.png");
  EXPECT_THAT(run.views.rejected[0].reason, HasSubstr("duplicate view of view_00.png"));
  EXPECT_EQ(run.views.rejected[1].file.filename(), "view_01_blurred.png");
  EXPECT_THAT(run.views.rejected[1].reason, HasSubstr("blurred"));
  EXPECT_EQ(run.views.rejected[2].file.filename(), "view_02_broken.png");
  EXPECT_THAT(run.views.rejected[2].reason, HasSubstr("cannot be decoded"));
}

TEST(SyntheticCalibration, ImagesWithoutBoardAreRejectedWithReason) {
  test::TempDir dir;
  write_views(dir.path(), rendered_views(true_pinhole()), 4);
  write_png(dir / "wall.png", cv::Mat(480, 640, CV_8UC1, cv::Scalar(128)));
  const CalibrationRun run = run_calibration(request_for(dir.path(), ModelKind::pinhole));
  ASSERT_EQ(run.views.rejected.size(), 1u);
  EXPECT_EQ(run.views.rejected[0].file.filename(), "wall.png");
  EXPECT_EQ(run.views.rejected[0].reason, "no 9x6 board found");
}

std::string error_of(const CalibrationRequest& request) {
  try {
    run_calibration(request);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(SyntheticCalibrationErrors, NoBoardInAnyImage) {
  test::TempDir dir;
  cv::Mat noise(240, 320, CV_8UC1);
  cv::RNG rng(7);
  for (int i = 0; i < 3; ++i) {
    rng.fill(noise, cv::RNG::UNIFORM, 0, 256);
    write_png(dir / ("noise" + std::to_string(i) + ".png"), noise);
  }
  EXPECT_THAT(error_of(request_for(dir.path(), ModelKind::pinhole)), HasSubstr("no image of 3 contained a 9x6 board"));
}

TEST(SyntheticCalibrationErrors, WrongBoardSizeFindsNoBoard) {
  test::TempDir dir;
  // Half-size copies: a search that finds nothing is slow at full size.
  for (int i = 0; i < 3; ++i) {
    cv::Mat small;
    cv::resize(rendered_views(true_pinhole())[i], small, cv::Size(320, 240), 0, 0, cv::INTER_AREA);
    write_png(dir / ("view_" + std::to_string(i) + ".png"), small);
  }
  CalibrationRequest request = request_for(dir.path(), ModelKind::pinhole);
  request.board = {8, 5, 0.03};
  EXPECT_THAT(error_of(request), HasSubstr("no image of 3 contained a 8x5 board"));
}

TEST(SyntheticCalibrationErrors, FewerUsableImagesThanNeeded) {
  test::TempDir dir;
  write_views(dir.path(), rendered_views(true_pinhole()), 2);
  write_png(dir / "wall.png", cv::Mat(480, 640, CV_8UC1, cv::Scalar(128)));
  const std::string message = error_of(request_for(dir.path(), ModelKind::pinhole));
  EXPECT_THAT(message, HasSubstr("only 2 of 3 images are usable, at least 3 are needed"));
  EXPECT_THAT(message, HasSubstr("wall.png: no 9x6 board found"));
}

TEST(SyntheticCalibrationErrors, MixedImageSizes) {
  test::TempDir dir;
  const auto& images = rendered_views(true_pinhole());
  write_views(dir.path(), images, 3);
  cv::Mat small;
  cv::resize(images[3], small, cv::Size(320, 240), 0, 0, cv::INTER_AREA);
  write_png(dir / "view_01_small.png", small);
  const std::string message = error_of(request_for(dir.path(), ModelKind::pinhole));
  EXPECT_THAT(message, HasSubstr("view_01_small.png"));
  EXPECT_THAT(message, HasSubstr("image is 320x240 pixels, but the first image (view_00.png) is 640x480"));
}

TEST(SyntheticCalibrationErrors, EmptyAndMissingFolders) {
  test::TempDir dir;
  test::write_text(dir / "notes.txt", "not an image");
  EXPECT_THAT(error_of(request_for(dir.path(), ModelKind::pinhole)), HasSubstr("no image files"));
  EXPECT_THAT(error_of(request_for(dir / "absent", ModelKind::pinhole)), HasSubstr("no such folder"));
}

TEST(SyntheticCalibrationErrors, AllFilesUndecodable) {
  test::TempDir dir;
  test::write_text(dir / "a.png", "x");
  test::write_text(dir / "b.jpg", "y");
  EXPECT_THAT(error_of(request_for(dir.path(), ModelKind::pinhole)),
              HasSubstr("none of the 2 image files could be decoded"));
}

}  // namespace
}  // namespace facadeslam::calib
