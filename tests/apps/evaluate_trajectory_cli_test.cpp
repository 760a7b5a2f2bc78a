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
#include <nlohmann/json.hpp>
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
bool is_one_line(const std::string& s) { return !s.empty() && s.back() == '\n' && s.find('\n') == s.size() - 1; }

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
  for (const char* key : {"pairs", "scale", "ate_rmse_m", "ate_mean_m", "ate_median_m", "ate_max_m", "rpe_trans_rmse_m",
                          "rpe_rot_rmse_deg", "path_length_m", "ate_percent_of_path"})
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
  const auto r =
      run("-q evaluate trajectory --gt " + quoted((data / "freiburg1_xyz-groundtruth.txt").string()) + " --est " +
          quoted((data / "freiburg1_xyz-ORB_kf_mono.txt").string()) + " --json " + quoted(json.string()));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = test::read_file_text(json);
  EXPECT_EQ(json_number(report, "pairs"), 32.0);
  EXPECT_NEAR(json_number(report, "scale"), 1.1056, 1e-4);
  EXPECT_NEAR(json_number(report, "ate_rmse_m"), 0.00975, 1e-4);
}

TEST_F(EvaluateTrajectoryCli, Se3KeepsTheScaleError) {
  write_pair();
  const auto json = dir_ / "eval.json";
  const auto r =
      run("-q evaluate trajectory " + inputs() + " --align se3 --rpe-delta 2 --json " + quoted(json.string()));
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

// KITTI pose files of a 260 m left bend (radius 300 m, a pose every 0.1 m):
// the ground truth, and the same drive at half the scale (a monocular
// estimate's arbitrary scale), 12 numbers a line, no times.
class EvaluateKittiCli : public EvaluateTrajectoryCli {
 protected:
  static constexpr double kRadius = 300.0;

  void write_kitti_pair(int poses) {
    std::ostringstream gt, est;
    char line[320];
    for (int i = 0; i < poses; ++i) {
      const double heading = 0.1 * i / kRadius, c = std::cos(heading), s = std::sin(heading);
      const double x = kRadius * (1.0 - c), z = kRadius * s;
      // Yaw about y (KITTI's camera: x right, y down, z forward).
      std::snprintf(line, sizeof line, "%.9f 0 %.9f %.9f 0 1 0 0 %.9f 0 %.9f %.9f\n", c, s, x, -s, c, z);
      gt << line;
      std::snprintf(line, sizeof line, "%.9f 0 %.9f %.9f 0 1 0 0 %.9f 0 %.9f %.9f\n", c, s, 0.5 * x, -s, c, 0.5 * z);
      est << line;
    }
    test::write_text(gt_path(), gt.str());
    test::write_text(est_path(), est.str());
  }
  nlohmann::json run_json(const std::string& options) {
    const auto json = dir_ / "eval.json";
    const auto r = run("-q evaluate trajectory " + inputs() + " " + options + " --json " + quoted(json.string()));
    EXPECT_EQ(r.exit_code, 0) << r.err;
    last_out_ = r.out;
    return nlohmann::json::parse(test::read_file_text(json));
  }
  std::string last_out_;
};

TEST_F(EvaluateKittiCli, TwoKittiFilesPairLineByLineAndGetTheDevkitFigures) {
  write_kitti_pair(2600);
  const nlohmann::json sim3 = run_json("");
  EXPECT_EQ(sim3.at("pairs"), 2600);
  EXPECT_NEAR(sim3.at("scale").get<double>(), 2.0, 1e-6);
  const nlohmann::json& k = sim3.at("kitti_relative");
  EXPECT_EQ(k.at("estimate_aligned_with"), "sim3");
  // First poses every 1 m: 160 segments of 100 m, 60 of 200 m.
  EXPECT_EQ(k.at("pairs"), 220);
  ASSERT_EQ(k.at("per_length").size(), 2u);
  EXPECT_EQ(k.at("per_length")[0].at("length_m"), 100.0);
  EXPECT_EQ(k.at("per_length")[0].at("pairs"), 160);
  EXPECT_EQ(k.at("per_length")[1].at("pairs"), 60);
  EXPECT_LT(k.at("translation_percent").get<double>(), 1e-4);  // the printed digits only
  EXPECT_LT(k.at("rotation_deg_per_100m").get<double>(), 1e-4);
  EXPECT_THAT(last_out_, HasSubstr("KITTI relative error (devkit segments, on the estimate aligned with sim3"));
  EXPECT_THAT(last_out_, HasSubstr("100 m     160"));

  // Rigid alignment keeps the half scale: half the 100 m chord, 50 % x 2R sin(L / 2R) / L.
  const nlohmann::json se3 = run_json("--align se3");
  const double chord_percent = 50.0 * 2.0 * kRadius * std::sin(100.0 / (2.0 * kRadius)) / 100.0;
  EXPECT_NEAR(se3.at("kitti_relative").at("per_length")[0].at("translation_percent").get<double>(), chord_percent,
              0.05);
  EXPECT_EQ(se3.at("kitti_relative").at("estimate_aligned_with"), "se3");
}

TEST_F(EvaluateKittiCli, PathShorterThan100mSaysSoAndHasNoFigures) {
  write_kitti_pair(600);  // 59.9 m
  const nlohmann::json report = run_json("");
  const nlohmann::json& k = report.at("kitti_relative");
  EXPECT_EQ(k.at("pairs"), 0);
  EXPECT_TRUE(k.at("translation_percent").is_null());
  EXPECT_TRUE(k.at("per_length").empty());
  EXPECT_THAT(k.at("no_segments").get<std::string>(), HasSubstr("(59.9 m) is not longer than the shortest segment"));
  EXPECT_THAT(last_out_, HasSubstr("no segments: the ground-truth path (59.9 m)"));
  EXPECT_NEAR(report.at("ate_rmse_m").get<double>(), 0.0, 1e-5);  // the ATE stands
}

// A KITTI ground truth against a TUM estimate: times from --gt-times or --rate.
TEST_F(EvaluateKittiCli, KittiAgainstTumNeedsTimesOrARate) {
  write_kitti_pair(1200);
  // The estimate as TUM at 10 Hz, starting at 0 s.
  std::ostringstream tum;
  char line[200];
  for (int i = 0; i < 1200; ++i) {
    const double heading = 0.1 * i / kRadius;
    std::snprintf(line, sizeof line, "%.6f %.9f 0 %.9f 0 %.12f 0 %.12f\n", 0.1 * i,
                  0.5 * kRadius * (1 - std::cos(heading)), 0.5 * kRadius * std::sin(heading), std::sin(0.5 * heading),
                  std::cos(0.5 * heading));
    tum << line;
  }
  test::write_text(est_path(), tum.str());

  const auto without = run("-q evaluate trajectory " + inputs());
  EXPECT_EQ(without.exit_code, 2);
  EXPECT_TRUE(is_one_line(without.err)) << without.err;
  EXPECT_THAT(without.err, HasSubstr("--gt-times: " + gt_path() + " is a KITTI pose file without timestamps and " +
                                     est_path() + " has timestamps: pass --gt-times FILE"));

  const nlohmann::json by_rate = run_json("--rate 10");
  EXPECT_EQ(by_rate.at("pairs"), 1200);
  EXPECT_NEAR(by_rate.at("scale").get<double>(), 2.0, 1e-6);
  EXPECT_EQ(by_rate.at("kitti_relative").at("pairs"), 20);  // 119.9 m: 100 m segments from 0..19 m

  std::string times;
  for (int i = 0; i < 1200; ++i) times += std::to_string(0.1 * i) + "\n";
  test::write_text(dir_ / "times.txt", times);
  const nlohmann::json by_times = run_json("--gt-times " + quoted((dir_ / "times.txt").string()));
  EXPECT_EQ(by_times.at("pairs"), 1200);
  EXPECT_EQ(by_times.at("kitti_relative").at("pairs"), 20);
}

TEST_F(EvaluateKittiCli, TimesFileOfAnotherLengthNamesBothFiles) {
  write_kitti_pair(30);
  test::write_text(dir_ / "times.txt", "0.0\n0.1\n");
  const auto r = run("-q evaluate trajectory " + inputs() + " --gt-times " + quoted((dir_ / "times.txt").string()) +
                     " --est-times " + quoted((dir_ / "times.txt").string()));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_TRUE(is_one_line(r.err)) << r.err;
  EXPECT_THAT(r.err, HasSubstr((dir_ / "times.txt").string() + ": has 2 timestamps but " + gt_path() +
                               " has 30 poses (expected one timestamp per pose)"));
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
