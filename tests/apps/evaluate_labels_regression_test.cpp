// Regression: `facadeslam evaluate labels` with the thesis genome on a fixed
// subset of the real LabelMeFacade data (first 20 training and 20 test
// images, 18-pixel grid, 6000 training keypoints drawn with the default
// seed: a 100-tree forest of depth 35 on all ~20000 keypoints takes ~45 s of
// CPU to train, and the cap barely changes the figure: 61.1 % on all, 61.9 %
// on 6000). The threshold sits below the measured figure with a margin, so
// the test fails when the descriptor, the forest or the ground-truth reading
// breaks, not on the small changes of a retuned detail. A class prior alone
// (always "building") scores 47 % here.
#include <cmath>
#include <cstdio>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "tests/apps/cli_run.hpp"
#include "tests/support/test_support.hpp"
#include "core/util/stopwatch.hpp"

namespace facadeslam {
namespace {

// Measured 2026-11-22 (Release build): overall 0.6185, average 0.2755, 28 s
// wall at load 10 on 2 cores (printed, not asserted: timing belongs in bench/).
constexpr double kMinimumOverallRate = 0.55;

TEST(EvaluateLabelsRegression, ThesisGenomeOnLabelMeFacadeSubset) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  test::TempDir dir;
  const auto json = dir / "report.json";
  std::string args = "-q evaluate labels --dataset ";
  args.append(test::shell_quoted((test::shared_data_dir() / "labelmefacade").string()))
      .append(" --descriptor modular --max-train 20 --max-test 20 --step 18 --max-samples 6000 --json ")
      .append(test::shell_quoted(json.string()));
  const Stopwatch start;
  const auto r = test::run_cli(FACADESLAM_BINARY, args, dir.path());
  const double seconds = start.elapsed_s();
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = test::read_file_text(json);
  const double overall = test::json_number(report, "overall_recognition_rate");
  const double average = test::json_number(report, "average_recognition_rate");
  std::printf("overall %.4f, average %.4f, %.1f s\n", overall, average, seconds);
  EXPECT_GT(overall, kMinimumOverallRate);
  EXPECT_TRUE(std::isfinite(average));
}

// The shipped model (models/README.md) on the same 20 test images and grid,
// without training. Measured 2026-12-02: overall 0.4626, average 0.4106.
// It was trained class-balanced, so the average recognition rate (mean
// per-class recall) is what it is for: always "building" would score ~0.11
// on it while scoring 0.47 overall, above this balanced forest.
constexpr double kShippedModelMinimumAverageRate = 0.36;

TEST(EvaluateLabelsRegression, ShippedModelOnLabelMeFacadeSubset) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  test::TempDir dir;
  const auto json = dir / "report.json";
  std::string args = "-q evaluate labels --dataset ";
  args.append(test::shell_quoted((test::shared_data_dir() / "labelmefacade").string()))
      .append(" --model ")
      .append(test::shell_quoted((test::source_dir() / "models/default.fsmodel").string()))
      .append(" --max-test 20 --step 18 --json ")
      .append(test::shell_quoted(json.string()));
  const auto r = test::run_cli(FACADESLAM_BINARY, args, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = test::read_file_text(json);
  const double average = test::json_number(report, "average_recognition_rate");
  std::printf("overall %.4f, average %.4f\n", test::json_number(report, "overall_recognition_rate"), average);
  EXPECT_GT(average, kShippedModelMinimumAverageRate);
}

// The street models (models/README.md) on CamVid's whole test split (drive
// 0006R0, at dusk; trained on the other two drives), keypoint-wise on the
// 9-pixel grid, as `evaluate labels --model` reports them. Measured
// 2026-12-07: colour 0.5928 overall / 0.5331 average, grey (the same frames
// turned grey) 0.6271 / 0.5246; the facade model scores 0.5527 / 0.4047 on
// the colour frames. Issue 42's bars: colour 0.62 / 0.52 (the overall one is
// not reached: road taken for pavement at dusk), grey 0.55 overall.
struct StreetModelCase {
  const char* model;
  bool grey;
  double min_overall, min_average;
};

class StreetModelRegression : public ::testing::TestWithParam<StreetModelCase> {};

TEST_P(StreetModelRegression, OnCamVidTestDrive) {
  FACADESLAM_REQUIRE_SHARED_DATA("camvid");
  const StreetModelCase& c = GetParam();
  test::TempDir dir;
  const auto json = dir / "report.json";
  std::string args = "-q evaluate labels --dataset ";
  args.append(test::shell_quoted((test::shared_data_dir() / "camvid").string()))
      .append(" --model ")
      .append(test::shell_quoted((test::source_dir() / "models" / c.model).string()))
      .append(c.grey ? " --grey" : "")
      .append(" --json ")
      .append(test::shell_quoted(json.string()));
  const auto r = test::run_cli(FACADESLAM_BINARY, args, dir.path());
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = test::read_file_text(json);
  const double overall = test::json_number(report, "overall_recognition_rate");
  const double average = test::json_number(report, "average_recognition_rate");
  std::printf("[  FIGURES ] %s on CamVid test%s: overall %.4f, average %.4f\n", c.model, c.grey ? " (grey)" : "",
              overall, average);
  EXPECT_GE(overall, c.min_overall);
  EXPECT_GE(average, c.min_average);
}

INSTANTIATE_TEST_SUITE_P(Shipped, StreetModelRegression,
                         ::testing::Values(StreetModelCase{"street.fsmodel", false, 0.58, 0.52},
                                           StreetModelCase{"street-grey.fsmodel", true, 0.60, 0.51}));

}  // namespace
}  // namespace facadeslam
