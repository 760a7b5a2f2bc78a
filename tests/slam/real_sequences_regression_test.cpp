// Issue 4's regression runs on real images (need ../shared/data):
//  - Middlebury templeRing: 19 views ~7.7 degrees apart around a plaster
//    temple, with exact cameras. Initialise on the first views, then track or
//    relocalise through the ring; every localised camera centre within 2 % of
//    the ring's diameter after Sim(3) alignment.
//  - ViSP's hand-held cube video (218 frames, no ground truth): initialises,
//    then tracks >= 90 % of the remaining frames with a median reprojection
//    error below 1.5 px.
// Synchronous mode, fixed seed: reproducible. Figures go to stdout
// ("[  FIGURES ]") and to the gtest properties.
#include <algorithm>
#include <cstdio>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/camera/camera_yaml.hpp"
#include "core/trajectory/metrics.hpp"
#include "core/trajectory/trajectory_io.hpp"
#include "sequences/open_sequence.hpp"
#include "slam/system.hpp"
#include "tests/slam/slam_test_run.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

// Every frame of an image folder through a synchronous System.
test::SlamRunLog run_folder(System& system, const fs::path& folder) {
  test::SlamRunLog log;
  auto source = open_sequence(folder, SequenceOptions{});
  while (auto frame = source->next()) log.add(system.process(std::move(*frame)));
  system.finish();
  return log;
}

std::string joined(const std::vector<std::size_t>& v) {
  std::string s;
  for (const std::size_t i : v) {
    if (!s.empty()) s += ' ';
    s += std::to_string(i);
  }
  return s.empty() ? "none" : s;
}

// templeR_par.txt: "name k11..k33 r11..r33 t1 t2 t3" per image, x = K [R | t] X.
std::map<std::string, SE3d> read_temple_cameras(const fs::path& file) {
  std::ifstream in(file);
  EXPECT_TRUE(in) << file;
  std::size_t count = 0;
  in >> count;
  std::map<std::string, SE3d> T_c_w;
  std::string name;
  while (in >> name) {
    double v[21];
    for (double& x : v) in >> x;
    Eigen::Matrix3d R;
    R << v[9], v[10], v[11], v[12], v[13], v[14], v[15], v[16], v[17];
    T_c_w[name] = SE3d(R, Eigen::Vector3d(v[18], v[19], v[20]));
  }
  EXPECT_EQ(T_c_w.size(), count) << file;
  return T_c_w;
}

// Radius of the circle through three points.
double circumradius(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c) {
  const double ab = (b - a).norm(), bc = (c - b).norm(), ca = (a - c).norm();
  const double area2 = (b - a).cross(c - a).norm();  // twice the triangle's area
  return ab * bc * ca / (2.0 * area2);
}

TEST(RealSequenceRegression, TempleRingCentresWithinTwoPercentOfTheRingDiameter) {
  FACADESLAM_REQUIRE_SHARED_DATA("middlebury/templeRing");
  const fs::path folder = test::shared_data_dir() / "middlebury" / "templeRing";
  const auto cameras = read_temple_cameras(folder / "templeR_par.txt");

  // Views 7.7 degrees apart, not video: every view may be a keyframe (the
  // default minimum of 20 frames between keyframes is a video's 2/3 s).
  SlamOptions options = test::synchronous_options();
  options.tracker.keyframe_min_frames = 1;
  System system(load_camera(test::source_dir() / "configs" / "camera" / "middlebury-temple.yaml"), options);
  const test::SlamRunLog log = run_folder(system, folder);
  ASSERT_TRUE(system.initialised()) << "templeRing never initialised";

  // Ground truth in the frames' timestamps (the folder's frames in name order).
  Trajectory gt;
  std::vector<Eigen::Vector3d> centres;
  auto source = open_sequence(folder, SequenceOptions{});
  while (auto frame = source->next()) {
    const auto it = cameras.find(frame->source.filename().string());
    ASSERT_NE(it, cameras.end()) << frame->source << " has no camera in templeR_par.txt";
    const SE3d T_w_c = it->second.inverse();
    gt.push_back({frame->timestamp, T_w_c.isometry()});
    centres.push_back(T_w_c.translation());
  }
  ASSERT_GE(centres.size(), 3u);
  const double diameter = 2.0 * circumradius(centres.front(), centres[centres.size() / 2], centres.back());

  std::vector<std::size_t> tracked, relocalised, lost;
  for (const FrameReport& f : log.frames) {
    if (f.status == FrameStatus::relocalised)
      relocalised.push_back(f.index);
    else if (f.has_pose)
      tracked.push_back(f.index);
    else if (static_cast<int>(f.index) > log.initialised_at())
      lost.push_back(f.index);
  }
  ASSERT_GE(log.estimate.size(), 3u);
  const TrajectoryEvaluation ate = evaluate_trajectory(gt, log.estimate, {});
  double worst = 0.0;
  for (std::size_t i = 0; i < ate.gt_positions.size(); ++i)
    worst = std::max(worst, (ate.gt_positions[i] - ate.aligned_est_positions[i]).norm());
  std::printf(
      "[  FIGURES ] templeRing: %zu views, initialised at view %d; tracked: %s; relocalised: %s; not localised: %s; "
      "ring diameter %.3f m, worst centre error %.4f m = %.2f %% of it, ATE RMSE %.4f m\n",
      log.frames.size(), log.initialised_at(), joined(tracked).c_str(), joined(relocalised).c_str(),
      joined(lost).c_str(), diameter, worst, 100.0 * worst / diameter, ate.ate_rmse_m);
  std::fflush(stdout);
  ::testing::Test::RecordProperty("worst_centre_error_percent_of_diameter", std::to_string(100.0 * worst / diameter));
  ::testing::Test::RecordProperty("localised", static_cast<int>(ate.pairs));

  EXPECT_LE(worst, 0.02 * diameter);
  EXPECT_TRUE(lost.empty()) << "views without a pose after initialisation: " << joined(lost);
}

TEST(RealSequenceRegression, VispCubeTracksNinetyPercentWithMedianErrorBelowOnePointFivePixels) {
  FACADESLAM_REQUIRE_SHARED_DATA("visp-cube");
  System system(load_camera(test::source_dir() / "configs" / "camera" / "visp-cube.yaml"), test::synchronous_options());
  const test::SlamRunLog log = run_folder(system, test::shared_data_dir() / "visp-cube");
  ASSERT_TRUE(system.initialised()) << "the cube video never initialised";

  const auto after = static_cast<std::size_t>(log.initialised_at() + 1);
  std::size_t tracked = 0;
  std::vector<double> rms;
  for (const FrameReport& f : log.frames) {
    if (f.index < after || !f.has_pose) continue;
    ++tracked;
    if (f.tracking.fine_found > 0) rms.push_back(f.tracking.inlier_rms_px);
  }
  const std::size_t remaining = log.frames.size() - after;
  ASSERT_GT(remaining, 0u);
  ASSERT_FALSE(rms.empty());
  std::nth_element(rms.begin(), rms.begin() + static_cast<std::ptrdiff_t>(rms.size() / 2), rms.end());
  const double median_rms = rms[rms.size() / 2];
  const double share = static_cast<double>(tracked) / static_cast<double>(remaining);
  std::printf(
      "[  FIGURES ] visp-cube: %zu frames, initialised at frame %d, tracked %zu of the %zu after it (%.1f %%), "
      "%zu keyframes, %zu points, median per-frame reprojection RMS %.3f px\n",
      log.frames.size(), log.initialised_at(), tracked, remaining, 100.0 * share, system.map().keyframe_count(),
      system.map().point_count(), median_rms);
  std::fflush(stdout);
  ::testing::Test::RecordProperty("tracked_percent", std::to_string(100.0 * share));
  ::testing::Test::RecordProperty("median_reprojection_px", std::to_string(median_rms));

  EXPECT_GE(share, 0.90);
  EXPECT_LT(median_rms, 1.5);
}

// KITTI odometry 06, frames 0-50: a car at ~12 m/s along a straight street
// (1.2 m between frames at 10 Hz), the camera looking forward. The thresholds
// are issue 16's. (Measured at this commit: initialised at frame 2, 48 of 48
// later frames tracked, 25 keyframes, ATE 0.042 % of the 57 m path; a sweep
// of the tracker's patch bound, dense radius and keyframe overlap around the
// defaults is in docs/benchmarks.md.)
TEST(RealSequenceRegression, KittiSnippetInitialisesEarlyAndTracksWithinTwoPercent) {
  FACADESLAM_REQUIRE_SHARED_DATA("kitti06-snippet");
  const fs::path dir = test::shared_data_dir() / "kitti06-snippet";
  System system(load_camera(dir / "camera.yaml"), test::synchronous_options());
  const test::SlamRunLog log = run_folder(system, dir / "rgb.txt");
  ASSERT_TRUE(system.initialised()) << "KITTI never initialised";
  EXPECT_LE(log.initialised_at(), 10);
  const std::size_t after = log.frames.size() - static_cast<std::size_t>(log.initialised_at()) - 1;
  const std::size_t tracked = log.tracked() - 1;  // the initialisation frame has a pose too
  const double share = after ? static_cast<double>(tracked) / static_cast<double>(after) : 0.0;
  ASSERT_GE(log.estimate.size(), 3u);
  const TrajectoryEvaluation ate = evaluate_trajectory(read_trajectory(dir / "groundtruth.txt"), log.estimate, {});
  std::printf(
      "[  FIGURES ] kitti06-snippet: %zu frames, initialised at frame %d, %zu of the %zu after it tracked "
      "(%.1f %%), %zu keyframes, ATE (Sim3) %.4f m = %.3f %% of the %.2f m path\n",
      log.frames.size(), log.initialised_at(), tracked, after, 100.0 * share, system.map().keyframe_count(),
      ate.ate_rmse_m, ate.ate_percent_of_path, ate.path_length_m);
  const TrajectoryEvaluation final_ate =
      evaluate_trajectory(read_trajectory(dir / "groundtruth.txt"), system.final_trajectory(), {});
  test::report_final_figures("kitti06-snippet", final_ate, ate);
  EXPECT_GE(share, 0.95);
  EXPECT_LE(ate.ate_percent_of_path, 2.0);
}

// The grey street with the semantic worker on (the shipped models: the grey
// one for these grey frames) and label-aware tracking: every map point
// labelled, tracking as good as without labels. KITTI has no label images,
// so the class counts are printed, not scored.
TEST(RealSequenceRegression, KittiSnippetIsLabelledByTheGreyModelAndStillTracked) {
  FACADESLAM_REQUIRE_SHARED_DATA("kitti06-snippet");
  const fs::path dir = test::shared_data_dir() / "kitti06-snippet";
  SlamOptions options = test::synchronous_options();
  options.semantics.enabled = true;
  options.semantics.model = test::source_dir() / "models" / "default.fsmodel";
  options.semantics.grey_model = test::source_dir() / "models" / "grey.fsmodel";
  System system(load_camera(dir / "camera.yaml"), options);
  const test::SlamRunLog log = run_folder(system, dir / "rgb.txt");
  system.finish();
  ASSERT_TRUE(system.initialised());
  const std::size_t after = log.frames.size() - static_cast<std::size_t>(log.initialised_at()) - 1;
  const std::size_t tracked = log.tracked() - 1;
  const TrajectoryEvaluation ate = evaluate_trajectory(read_trajectory(dir / "groundtruth.txt"), log.estimate, {});
  std::size_t labelled = 0, points = 0, down_weighted = 0;
  std::map<std::string, std::size_t> counts;
  for (const PointSnapshot& p : system.map().snapshot_points()) {
    ++points;
    const SemanticLabel label = p.point->label();
    if (label.label == kUnlabelled) continue;
    ++labelled;
    ++counts[std::string(kSemanticClasses[label.label].name)];
  }
  for (const FrameReport& f : log.frames) down_weighted += static_cast<std::size_t>(f.tracking.points_down_weighted);
  std::printf(
      "[  FIGURES ] kitti06-snippet, semantics on: %zu of the %zu frames after initialisation tracked, ATE "
      "%.3f %% of the path; %zu of %zu points labelled:",
      tracked, after, ate.ate_percent_of_path, labelled, points);
  for (const auto& [name, count] : counts) std::printf(" %s %zu", name.c_str(), count);
  std::printf("; %zu measurements down-weighted for their class\n", down_weighted);
  const auto stats = system.semantic_stats();
  ASSERT_TRUE(stats.has_value());
  EXPECT_TRUE(stats->grey_model);
  EXPECT_GT(stats->grey_keyframes, 0u);
  EXPECT_GE(static_cast<double>(labelled), 0.9 * static_cast<double>(points));
  EXPECT_GT(down_weighted, 0u) << "label-aware tracking never weighed a point down";
  EXPECT_GE(static_cast<double>(tracked), 0.95 * static_cast<double>(after));
  EXPECT_LE(ate.ate_percent_of_path, 2.0);
}

}  // namespace
}  // namespace facadeslam
