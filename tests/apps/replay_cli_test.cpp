// End to end: `facadeslam replay` on sequences the test makes itself (the
// demo scene rendered by `facadeslam synth` from the committed photos, or
// plain images), for issue 4's bad-input cases: a camera of another size, an
// empty sequence, a sequence without parallax (exit code 3 and a report
// saying so), a corrupt frame mid-sequence (counted, skipped, tracking goes
// on) and a map file made with another camera.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <string>

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/imgproc.hpp>

#include "core/trajectory/trajectory_io.hpp"
#include "tests/apps/cli_run.hpp"
#include "tests/support/smooth_texture.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;
using ::testing::HasSubstr;

std::string quoted(const fs::path& p) { return test::shell_quoted(p.string()); }

fs::path synthetic_camera() { return test::source_dir() / "configs" / "camera" / "synthetic-640x480.yaml"; }

class ReplayCli : public ::testing::Test {
 protected:
  void SetUp() override { fs::create_directories(scratch()); }
  fs::path scratch() const { return dir_ / "scratch"; }
  test::CliResult run(const std::string& arguments) { return test::run_cli(FACADESLAM_BINARY, arguments, scratch()); }

  // The demo scene's first `frames` frames, rendered into DIR/name.
  fs::path render_demo(const std::string& name, int frames) {
    const fs::path out = dir_ / name;
    std::string args = "-q synth --scene ";
    args.append(quoted(test::source_dir() / "configs" / "scenes" / "demo.yaml"))
        .append(" --out ")
        .append(quoted(out))
        .append(" --frames ")
        .append(std::to_string(frames));
    const test::CliResult r = run(args);
    EXPECT_EQ(r.exit_code, 0) << r.err;
    return out;
  }

  // A folder of `count` copies of one image with the synthetic camera.
  fs::path still_folder(const std::string& name, int count, int width, int height) {
    const fs::path folder = dir_ / name;
    fs::create_directories(folder);
    const cv::Mat image = test::smooth_random_texture(width, height, 7);
    for (int i = 0; i < count; ++i) {
      char file[32];
      std::snprintf(file, sizeof file, "%04d.png", i);
      cv::imwrite((folder / file).string(), image);
    }
    return folder;
  }

  static void expect_one_line_error(const test::CliResult& r, int exit_code, const std::string& mention) {
    EXPECT_EQ(r.exit_code, exit_code) << r.err;
    EXPECT_THAT(r.err, HasSubstr(mention));
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
  }

  test::TempDir dir_;
};

// Runs anywhere: the demo, the shipped model and the semantic settings are
// found beside the executable, not in the current folder, so a replay from
// any folder labels its map as it does from the project's own.
TEST_F(ReplayCli, TheDemoFromAnotherFolderIsLabelledWithTheShippedModel) {
  if (!fs::exists(test::source_dir() / "data" / "demo" / "sequence" / "rgb.txt"))
    GTEST_SKIP() << "the embedded demo is not rendered (scripts/make-demo)";
  const fs::path elsewhere = dir_ / "elsewhere";
  fs::create_directories(elsewhere);
  const fs::path previous = fs::current_path();
  fs::current_path(elsewhere);
  const test::CliResult r = run("replay --sync --limit 40 --out labelled");
  fs::current_path(previous);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  EXPECT_THAT(r.err, ::testing::Not(HasSubstr("no model")));
  const std::string report = test::read_file_text(elsewhere / "labelled" / "report.json");
  EXPECT_GT(test::json_number(report, "points_labelled"), 100.0) << report.substr(0, 2000);
}

TEST_F(ReplayCli, CameraOfAnotherSizeIsRejectedNamingBoth) {
  const fs::path folder = still_folder("small", 3, 320, 240);
  std::string args = "-q replay ";
  args.append(quoted(folder)).append(" --camera ").append(quoted(synthetic_camera()));
  args.append(" --out ").append(quoted(dir_ / "out"));
  const test::CliResult r = run(args);
  expect_one_line_error(r, 1, "image is 320x240 but the camera");
  EXPECT_THAT(r.err, HasSubstr("synthetic-640x480.yaml"));
  EXPECT_FALSE(fs::exists(dir_ / "out" / "report.json"));
}

TEST_F(ReplayCli, EmptySequenceIsRejected) {
  const fs::path folder = dir_ / "empty";
  fs::create_directories(folder);
  std::string args = "-q replay ";
  args.append(quoted(folder)).append(" --camera ").append(quoted(synthetic_camera()));
  args.append(" --out ").append(quoted(dir_ / "out"));
  expect_one_line_error(run(args), 1, "no images found");
}

TEST_F(ReplayCli, NoParallaxEndsWithExitCodeThreeAndAReport) {
  const fs::path folder = still_folder("still", 12, 640, 480);
  const fs::path out = dir_ / "out";
  std::string args = "-q replay ";
  args.append(quoted(folder)).append(" --camera ").append(quoted(synthetic_camera()));
  args.append(" --sync --out ").append(quoted(out));
  const test::CliResult r = run(args);
  expect_one_line_error(r, 3, "never initialised");
  const std::string report = test::read_file_text(out / "report.json");
  EXPECT_THAT(report, HasSubstr("\"initialised\": false"));
  EXPECT_EQ(test::json_number(report, "frames"), 12.0);
  EXPECT_EQ(test::json_number(report, "frames_tracked"), 0.0);
}

TEST_F(ReplayCli, CorruptFrameMidSequenceIsCountedAndSkipped) {
  const fs::path sequence = render_demo("demo", 60);
  {
    std::ofstream corrupt(sequence / "rgb" / "000045.png", std::ios::binary | std::ios::trunc);
    corrupt << "not a PNG";
  }
  const fs::path out = dir_ / "out";
  std::string args = "-q replay ";
  args.append(quoted(sequence)).append(" --sync --out ").append(quoted(out));
  const test::CliResult r = run(args);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = test::read_file_text(out / "report.json");
  EXPECT_THAT(report, HasSubstr("\"initialised\": true"));
  EXPECT_EQ(test::json_number(report, "frames_corrupt_skipped"), 1.0);
  EXPECT_EQ(test::json_number(report, "frames"), 59.0);
  EXPECT_EQ(test::json_number(report, "frames_lost"), 0.0);
  // The demo initialises in its first 25 frames; every frame after it,
  // including those after the corrupt one, is tracked.
  EXPECT_GE(test::json_number(report, "frames_tracked"), 34.0);
}

// Issue 20's first rule: a missing ground truth, an output that is a file or
// cannot be made, and counts out of range fail before any frame is read,
// with one line, writing nothing.
TEST_F(ReplayCli, BadGroundTruthOutputsAndCountsFailBeforeAnyFrame) {
  const fs::path sequence = render_demo("tiny", 3);
  const std::string replay = "-q replay " + quoted(sequence / "rgb.txt") + " --sync ";
  const fs::path out = dir_ / "never-written";
  test::CliResult r = run(replay + "--gt " + quoted(dir_ / "missing.txt") + " --out " + quoted(out));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("missing.txt"));
  EXPECT_FALSE(fs::exists(out / "trajectory.txt"));
  { std::ofstream(dir_ / "a-file") << "x"; }
  r = run(replay + "--out " + quoted(dir_ / "a-file"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_THAT(r.err, HasSubstr("a-file"));
  for (const char* bad : {"--start -5", "--limit=-1", "--stride 0"}) {
    r = run(replay + bad + " --out " + quoted(out));
    EXPECT_EQ(r.exit_code, 2) << bad;
    EXPECT_EQ(std::count(r.err.begin(), r.err.end(), '\n'), 1) << r.err;
    EXPECT_LT(r.err.size(), 200u) << bad << ": " << r.err;
  }
  EXPECT_FALSE(fs::exists(out / "report.json"));
}

// Ctrl-C mid-replay (issue 20): the replay stops after the current frame,
// finishes the map and writes a complete output set that says it was
// interrupted, exit code 130, no temporary files left.
TEST_F(ReplayCli, CtrlCStopsAtTheNextFrameAndWritesCompleteOutputs) {
  const fs::path demo = test::source_dir() / "data" / "demo" / "sequence";
  if (!fs::exists(demo / "rgb.txt")) GTEST_SKIP() << "the embedded demo is not rendered (scripts/make-demo)";
  const fs::path out = dir_ / "interrupted", log = dir_ / "interrupted.log", code = dir_ / "code.txt";
  // In the background; SIGINT once the map exists (its log line), then the exit code.
  // Built by appending: GCC 12 warns falsely on "literal" + std::string.
  std::string script = test::shell_quoted(FACADESLAM_BINARY);
  script.append(" replay ").append(quoted(demo / "rgb.txt")).append(" --sync --out ").append(quoted(out));
  script.append(" 2> ").append(quoted(log)).append(" & pid=$!; for i in $(seq 1 200); do grep -q 'map initialised' ");
  script.append(quoted(log)).append(" 2>/dev/null && break; sleep 0.05; done; kill -INT $pid; wait $pid; echo $? > ");
  script.append(quoted(code));
  // From a script file: the quoted paths inside need no second quoting.
  const fs::path script_file = dir_ / "ctrl-c.sh";
  { std::ofstream(script_file) << script << "\n"; }
  std::string command = "/bin/sh ";
  command.append(quoted(script_file));
  ASSERT_EQ(std::system(command.c_str()), 0);
  EXPECT_EQ(test::read_file_text(code), "130\n") << test::read_file_text(log);
  const std::string report = test::read_file_text(out / "report.json");
  EXPECT_THAT(report, HasSubstr("\"interrupted\": true"));
  EXPECT_LT(test::json_number(report, "frames"), 150.0);
  for (const char* file : {"trajectory.txt", "trajectory_online.txt", "keyframes.txt", "map.ply", "map.fslmap"})
    EXPECT_TRUE(fs::exists(out / file)) << file;
  for (const auto& entry : fs::directory_iterator(out))
    EXPECT_NE(entry.path().filename().string().front(), '.') << "temporary file left: " << entry.path();
}

// A frame rate that makes the motion model useless (every 10th frame of the
// demo: 1/3 s and ~10 cm between frames, views ~3 degrees apart): tracked
// through by the relocaliser, or lost gracefully, never a crash or a
// trajectory far off the truth. Measured: 11 of 15 frames, 0 lost, ATE 0.18 %.
TEST_F(ReplayCli, AStrideOfTenIsTrackedOrLostGracefully) {
  const fs::path demo = test::source_dir() / "data" / "demo" / "sequence";
  if (!fs::exists(demo / "rgb.txt")) GTEST_SKIP() << "the embedded demo is not rendered (scripts/make-demo)";
  const fs::path out = dir_ / "stride-10";
  const test::CliResult r = run("-q replay " + quoted(demo / "rgb.txt") + " --stride 10 --sync --gt " +
                                quoted(demo / "groundtruth.txt") + " --semantics off --out " + quoted(out));
  ASSERT_TRUE(r.exit_code == 0 || r.exit_code == 3) << r.err;  // 3: never initialised, said so
  const std::string report = test::read_file_text(out / "report.json");
  EXPECT_EQ(test::json_number(report, "frames"), 15.0);
  if (r.exit_code == 0 && report.find("ate_percent_of_path") != std::string::npos) {
    EXPECT_LT(test::json_number(report, "ate_percent_of_path"), 5.0);
  }
}

// Every output a user gets; with ground truth the ATE figures and the top
// view PNG, without it neither.
TEST_F(ReplayCli, WritesEveryOutputAndWithGroundTruthTheAteAndItsPlot) {
  const fs::path sequence = render_demo("demo", 50);
  for (const bool with_gt : {true, false}) {
    const fs::path out = dir_ / (with_gt ? "with-gt" : "without-gt");
    std::string args = "-q replay ";
    args.append(quoted(sequence / "rgb.txt")).append(" --sync --out ").append(quoted(out));
    if (with_gt) args.append(" --gt ").append(quoted(sequence / "groundtruth.txt"));
    const test::CliResult r = run(args);
    ASSERT_EQ(r.exit_code, 0) << r.err;
    for (const char* file :
         {"trajectory.txt", "trajectory_online.txt", "keyframes.txt", "map.ply", "map.fslmap", "report.json"})
      EXPECT_TRUE(fs::exists(out / file)) << file;
    // The final trajectory and the online one: the same frames, one line each.
    const auto lines = [](const std::string& text) { return std::count(text.begin(), text.end(), '\n'); };
    const std::string final = test::read_file_text(out / "trajectory.txt");
    const std::string online = test::read_file_text(out / "trajectory_online.txt");
    EXPECT_GE(lines(final), 20);
    EXPECT_EQ(lines(final), lines(online));
    const std::string report = test::read_file_text(out / "report.json");
    EXPECT_EQ(report.find("ate_percent_of_path") != std::string::npos, with_gt) << report;
    EXPECT_EQ(report.find("\"ate_online\"") != std::string::npos, with_gt) << report;
    EXPECT_EQ(fs::exists(out / "trajectory.png"), with_gt);
    if (with_gt) {
      const cv::Mat plot = cv::imread((out / "trajectory.png").string());
      EXPECT_FALSE(plot.empty());
      EXPECT_LT(test::json_number(report, "ate_percent_of_path"), 10.0);
      EXPECT_LT(nlohmann::json::parse(report).at("ate_online").at("ate_percent_of_path").get<double>(), 10.0);
    }
  }
}

// `replay --gt` with a KITTI pose file (12 numbers a line, no times): line
// i is the pose of frame i of the sequence, at the time rgb.txt gives that
// frame, also when --start and --stride skip frames. The KITTI 06 snippet's
// poses written both ways give the same figures; its 60 m of path are too
// short for KITTI's shortest segment (100 m), which the report says.
TEST_F(ReplayCli, KittiGroundTruthLineIsTheFramesPoseUnderStartAndStride) {
  FACADESLAM_REQUIRE_SHARED_DATA("kitti06-snippet");
  const fs::path snippet = test::shared_data_dir() / "kitti06-snippet";
  const fs::path kitti_gt = dir_ / "06-poses.txt";
  {
    std::ofstream out(kitti_gt);
    char line[400];
    for (const StampedPose& pose : read_trajectory(snippet / "groundtruth.txt")) {
      const Eigen::Matrix<double, 3, 4> m = pose.T_w_c.matrix().topRows<3>();
      std::snprintf(line, sizeof line, "%.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n",
                    m(0, 0), m(0, 1), m(0, 2), m(0, 3), m(1, 0), m(1, 1), m(1, 2), m(1, 3), m(2, 0), m(2, 1), m(2, 2),
                    m(2, 3));
      out << line;
    }
  }
  nlohmann::json reports[2];
  const fs::path ground_truths[2] = {snippet / "groundtruth.txt", kitti_gt};
  for (int k = 0; k < 2; ++k) {
    const fs::path out = dir_ / (k == 0 ? "tum-gt" : "kitti-gt");
    const test::CliResult r = run("-q replay " + quoted(snippet / "rgb.txt") + " --start 1 --stride 2 --sync " +
                                  "--semantics off --gt " + quoted(ground_truths[k]) + " --out " + quoted(out));
    ASSERT_EQ(r.exit_code, 0) << r.err;
    reports[k] = nlohmann::json::parse(test::read_file_text(out / "report.json"));
  }
  const nlohmann::json& tum = reports[0];
  const nlohmann::json& kitti = reports[1];
  ASSERT_TRUE(kitti.contains("ate_rmse_m")) << kitti.dump();
  EXPECT_EQ(kitti.at("frames"), 25);  // frames 1, 3, ... 49
  EXPECT_EQ(kitti.at("ate_pairs"), tum.at("ate_pairs"));
  EXPECT_NEAR(kitti.at("ate_rmse_m").get<double>(), tum.at("ate_rmse_m").get<double>(), 1e-9);
  EXPECT_NEAR(kitti.at("path_length_m").get<double>(), tum.at("path_length_m").get<double>(), 1e-9);
  EXPECT_LT(kitti.at("ate_percent_of_path").get<double>(), 2.0);  // the right poses, not a shifted list
  for (const nlohmann::json* report : {&tum, &kitti}) {
    const nlohmann::json& relative = report->at("kitti_relative");
    EXPECT_EQ(relative.at("pairs"), 0);
    EXPECT_EQ(relative.at("estimate_aligned_with"), "sim3");
    EXPECT_THAT(relative.at("no_segments").get<std::string>(),
                HasSubstr("is not longer than the shortest segment (100 m)"));
  }
}

TEST_F(ReplayCli, MapFromAnotherCameraIsRejected) {
  const fs::path sequence = render_demo("demo", 40);
  const fs::path map = dir_ / "demo.fslmap";
  std::string save = "-q replay ";
  save.append(quoted(sequence)).append(" --sync --save-map ").append(quoted(map));
  save.append(" --out ").append(quoted(dir_ / "first"));
  ASSERT_EQ(run(save).exit_code, 0);
  ASSERT_TRUE(fs::exists(map));

  std::string load = "-q replay ";
  load.append(quoted(sequence)).append(" --camera ");
  load.append(quoted(test::source_dir() / "configs" / "camera" / "opencv-left.yaml"));
  load.append(" --sync --load-map ").append(quoted(map)).append(" --out ").append(quoted(dir_ / "second"));
  expect_one_line_error(run(load), 1, "map was made with camera");
}

// The semantic worker with the shipped model labels the map; `--semantics
// off` leaves it unlabelled; a model that is not there fails before any
// frame, naming it, with nothing written.
TEST_F(ReplayCli, SemanticsLabelTheMapAndAMissingModelFailsFirst) {
  const fs::path sequence = render_demo("demo", 40);
  const fs::path model = test::source_dir() / "models" / "default.fsmodel";
  std::string on = "-q replay ";
  on.append(quoted(sequence))
      .append(" --sync --model ")
      .append(quoted(model))
      .append(" --out ")
      .append(quoted(dir_ / "on"));
  const test::CliResult r = run(on);
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = test::read_file_text(dir_ / "on" / "report.json");
  EXPECT_GT(test::json_number(report, "points_labelled"), 50.0) << report;
  EXPECT_EQ(test::json_number(report, "points_unlabelled"), 0.0) << report;

  std::string off = "-q replay ";
  off.append(quoted(sequence)).append(" --sync --semantics off --out ").append(quoted(dir_ / "off"));
  ASSERT_EQ(run(off).exit_code, 0);
  EXPECT_THAT(test::read_file_text(dir_ / "off" / "report.json"), HasSubstr("\"enabled\": false"));

  std::string missing = "-q replay ";
  missing.append(quoted(sequence)).append(" --sync --model ").append(quoted(dir_ / "absent.fsmodel"));
  missing.append(" --out ").append(quoted(dir_ / "missing"));
  expect_one_line_error(run(missing), 1, "absent.fsmodel");
  EXPECT_FALSE(fs::exists(dir_ / "missing"));

  // The grey model is loaded before any frame too, colour sequence or not.
  EXPECT_THAT(report, HasSubstr("\"grey_model\""));
  std::string missing_grey = "-q replay ";
  missing_grey.append(quoted(sequence)).append(" --sync --grey-model ").append(quoted(dir_ / "absent-grey.fsmodel"));
  missing_grey.append(" --out ").append(quoted(dir_ / "missing-grey"));
  expect_one_line_error(run(missing_grey), 1, "absent-grey.fsmodel");
  EXPECT_FALSE(fs::exists(dir_ / "missing-grey"));
}

// A synthetic sequence's label/ folder is found on its own and gives the
// report its label accuracy; a --gt-labels folder that does not fit the
// sequence (no such folder, a label image of another size) fails before the
// work, naming the file, with nothing written.
TEST_F(ReplayCli, GroundTruthLabelsGiveTheLabelAccuracyAndBadOnesFailFirst) {
  const fs::path sequence = render_demo("demo", 40);
  std::string on = "-q replay ";
  on.append(quoted(sequence)).append(" --sync --out ").append(quoted(dir_ / "on"));
  const test::CliResult r = run(on + " --model " + quoted(test::source_dir() / "models" / "default.fsmodel"));
  ASSERT_EQ(r.exit_code, 0) << r.err;
  const std::string report = test::read_file_text(dir_ / "on" / "report.json");
  const double accuracy = test::json_number(report, "label_accuracy");
  EXPECT_GT(accuracy, 0.3) << report;
  EXPECT_LE(accuracy, 1.0) << report;
  EXPECT_THAT(report, HasSubstr("\"label_accuracy_per_class\""));
  EXPECT_THAT(report, HasSubstr("\"points_down_weighted_by_tracker\""));
  // The confusion matrix holds every evaluated point; its diagonal is the accuracy.
  const nlohmann::json semantics = nlohmann::json::parse(report).at("semantics");
  double all = 0, diagonal = 0;
  for (const auto& row : semantics.at("label_confusion").items())
    for (const auto& cell : row.value().items()) {
      all += cell.value().get<double>();
      if (cell.key() == row.key()) diagonal += cell.value().get<double>();
    }
  EXPECT_EQ(all, semantics.at("label_accuracy_points").get<double>());
  EXPECT_NEAR(diagonal / all, accuracy, 1e-12);

  std::string absent = "-q replay ";
  absent.append(quoted(sequence)).append(" --sync --gt-labels ").append(quoted(dir_ / "nowhere"));
  absent.append(" --out ").append(quoted(dir_ / "absent"));
  expect_one_line_error(run(absent), 1, "nowhere");
  EXPECT_FALSE(fs::exists(dir_ / "absent"));

  const fs::path small = dir_ / "small-labels";
  fs::create_directories(small);
  for (const auto& entry : fs::directory_iterator(sequence / "label")) {
    cv::Mat label = cv::imread(entry.path().string(), cv::IMREAD_COLOR);
    cv::resize(label, label, {label.cols / 2, label.rows / 2}, 0, 0, cv::INTER_NEAREST);
    cv::imwrite((small / entry.path().filename()).string(), label);
  }
  std::string wrong = "-q replay ";
  wrong.append(quoted(sequence)).append(" --sync --gt-labels ").append(quoted(small));
  wrong.append(" --out ").append(quoted(dir_ / "wrong"));
  expect_one_line_error(run(wrong), 1, "label image is 320x240, the frame is 640x480");
  EXPECT_FALSE(fs::exists(dir_ / "wrong"));
}

}  // namespace
}  // namespace facadeslam
