// End to end: the built `facadeslam` binary on small trajectories written
// here, checking exit codes, the JSON report, the plot and the one-line
// error messages.
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/imgcodecs.hpp>

#include "tests/apps/cli_run.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

using ::testing::HasSubstr;

std::string quoted(const std::string& s) { return test::shell_quoted(s); }

class EvaluateTrajectoryCli : public ::testing::Test {
 protected:
  test::CliResult run(const std::string& arguments) { return test::run_cli(FACADESLAM_BINARY, arguments, dir_.path()); }

  // A rising helix (with rotations) as TUM; the estimate is the same motion
  // at half the scale, shifted, with timestamps 3 ms late.
  void write_pair() {
    std::ostringstream gt, est;
    gt << "# timestamp tx ty tz qx qy qz qw\n";
    char line[256];
    for (int i = 0; i < 60; ++i) {
      const double a = 0.15 * i, t = 100.0 + 0.1 * i;
      const double x = 2.0 * std::cos(a), y = 2.0 * std::sin(a), z = 0.05 * i;
      const double qz = std::sin(0.5 * a), qw = std::cos(0.5 * a);
      std::snprintf(line, sizeof line, "%.4f %.6f %.6f %.6f 0 0 %.9f %.9f\n", t, x, y, z, qz, qw);
      gt << line;
      std::snprintf(line, sizeof line, "%.6f %.9f %.9f %.9f 0 0 %.9f %.9f\n", t + 0.003, 0.5 * x + 1.0, 0.5 * y,
                    0.5 * z - 2.0, qz, qw);
      est << line;
    }
    test::write_text(gt_path(), gt.str());
    test::write_text(est_path(), est.str());
  }

  std::string gt_path() const { return (dir_ / "gt.txt").string(); }
  std::string est_path() const { return (dir_ / "est.txt").string(); }
  std::string inputs() const { return "--gt " + quoted(gt_path()) + " --est " + quoted(est_path()); }

  test::TempDir dir_;
};

// One line of text ending in a newline.
bool is_one_line(const std::string& s) {
  return !s.empty() && s.back() == '\n' && s.find('\n') == s.size() - 1;
}

// `"key":` as it appears in the report (appended, for the same GCC 12 warning).
std::string json_key(const std::string& key) {
  std::string k;
  k.append(1, '"').append(key).append("\":");
  return k;
}

double json_number(const std::string& json, const std::string& key) {
  const auto at = json.find(json_key(key));
  if (at == std::string::npos) return std::nan("");
  return std::strtod(json.c_str() + at + key.size() + 3, nullptr);
}

TEST_F(EvaluateTrajectoryCli, WritesTableJsonAndPlot) {
  write_pair();
  const auto json = dir_ / "out" / "eval.json";
  const auto png = dir_ / "out" / "top.png";
  const auto r = run("-q evaluate trajectory " + inputs() + " --json " + quoted(json.string()) + " --plot " +
                     quoted(png.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.out, HasSubstr("ATE RMSE"));
  EXPECT_THAT(r.out, HasSubstr("RPE rotation RMSE"));
  EXPECT_EQ(r.err, "");

  const std::string report = test::read_file_text(json);
  for (const char* key : {"pairs", "scale", "ate_rmse_m", "ate_mean_m", "ate_median_m", "ate_max_m",
                          "rpe_trans_rmse_m", "rpe_rot_rmse_deg", "path_length_m", "ate_percent_of_path"})
    EXPECT_THAT(report, HasSubstr(json_key(key))) << key;
  EXPECT_EQ(json_number(report, "pairs"), 60.0);
  EXPECT_NEAR(json_number(report, "scale"), 2.0, 1e-6);
  EXPECT_LT(json_number(report, "ate_rmse_m"), 1e-5);  // only the printed digits differ

  const cv::Mat image = cv::imread(png.string(), cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.size(), cv::Size(1000, 800));
}

// The README's first command, on the fr1_xyz files the project ships.
TEST_F(EvaluateTrajectoryCli, BundledFr1XyzMatchesTheReference) {
  const auto data = test::source_dir() / "data" / "trajectories";
  const auto json = dir_ / "fr1.json";
  const auto r = run("-q evaluate trajectory --gt " + quoted((data / "freiburg1_xyz-groundtruth.txt").string()) +
                     " --est " + quoted((data / "freiburg1_xyz-ORB_kf_mono.txt").string()) + " --json " +
                     quoted(json.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = test::read_file_text(json);
  EXPECT_EQ(json_number(report, "pairs"), 32.0);
  EXPECT_NEAR(json_number(report, "scale"), 1.1056, 1e-4);
  EXPECT_NEAR(json_number(report, "ate_rmse_m"), 0.00975, 1e-4);
}

TEST_F(EvaluateTrajectoryCli, Se3KeepsTheScaleError) {
  write_pair();
  const auto json = dir_ / "eval.json";
  const auto r = run("-q evaluate trajectory " + inputs() + " --align se3 --rpe-delta 2 --json " + quoted(json.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = test::read_file_text(json);
  EXPECT_EQ(json_number(report, "scale"), 1.0);
  EXPECT_GT(json_number(report, "ate_rmse_m"), 0.1);
  EXPECT_EQ(json_number(report, "rpe_delta"), 2.0);
}

TEST_F(EvaluateTrajectoryCli, MissingFileIsOneLineAndNonZero) {
  write_pair();
  const auto missing = (dir_ / "nope.txt").string();
  const auto r = run("evaluate trajectory --gt " + quoted(gt_path()) + " --est " + quoted(missing));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(is_one_line(r.err)) << r.err;
  EXPECT_THAT(r.err, HasSubstr(missing));
  EXPECT_THAT(r.err, HasSubstr("no such file"));
  EXPECT_EQ(r.out, "");
}

TEST_F(EvaluateTrajectoryCli, UnparsableLineNamesFileAndLine) {
  write_pair();
  test::write_text(est_path(), "100.0 0 0 0 0 0 0 1\n100.1 0 0 oops 0 0 0 1\n");
  const auto r = run("evaluate trajectory " + inputs());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(is_one_line(r.err)) << r.err;
  EXPECT_THAT(r.err, HasSubstr(est_path() + ":2: expected 8 numbers"));
}

TEST_F(EvaluateTrajectoryCli, NoAssociatedPairsIsAnError) {
  write_pair();
  test::write_text(est_path(), "5.0 0 0 0 0 0 0 1\n6.0 1 0 0 0 0 0 1\n7.0 1 1 0 0 0 0 1\n");
  const auto r = run("evaluate trajectory " + inputs());
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(is_one_line(r.err)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("only 0 of 3 estimated poses"));
}

TEST_F(EvaluateTrajectoryCli, BadAlignValueIsAUsageError) {
  write_pair();
  const auto r = run("evaluate trajectory " + inputs() + " --align affine");
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(is_one_line(r.err)) << r.err;
  EXPECT_THAT(r.err, HasSubstr("--align"));
}

TEST_F(EvaluateTrajectoryCli, UnwritablePlotIsAnError) {
  write_pair();
  test::write_text(dir_ / "file", "x");
  const auto r = run("-q evaluate trajectory " + inputs() + " --plot " + quoted((dir_ / "file" / "p.png").string()));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(is_one_line(r.err)) << r.err;
}

}  // namespace
}  // namespace facadeslam
