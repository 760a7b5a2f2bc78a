// Issue 4's regression runs: the SLAM system in synchronous mode (fixed seed,
// reproducible bit for bit) over the synthetic streets, with the issue's
// thresholds. Each test renders its scene (needs ../shared/data) and prints
// its figures ("[  FIGURES ]" lines; also gtest properties).
#include <cstdio>

#include <gtest/gtest.h>

#include "core/map/map_io.hpp"
#include "tests/slam/slam_test_run.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

std::string list(const std::vector<std::size_t>& v) {
  std::string s;
  for (std::size_t i = 0; i < v.size() && i < 30; ++i) {
    if (!s.empty()) s += ' ';
    s += std::to_string(v[i]);
  }
  if (v.size() > 30) s += " ...";
  return s;
}

// Whole sequence: initialises, then no frame lost, ATE within `max_percent`
// of the path length.
void expect_tracks_whole_street(const std::string& name, double max_percent,
                                const SlamOptions& options = test::synchronous_options()) {
  test::SceneFrames scene(test::scene_file(name));
  System system(scene.camera(), options);
  test::SlamRunLog log;
  test::run_frames(system, scene, 0, scene.size(), log);
  system.finish();
  ASSERT_TRUE(system.initialised());
  ASSERT_GE(log.estimate.size(), 3u);
  const TrajectoryEvaluation ate = test::evaluate(scene, log.estimate);
  test::report_figures(name, log, ate);
  const Trajectory final = system.final_trajectory();
  ASSERT_EQ(final.size(), log.estimate.size());
  const TrajectoryEvaluation final_ate = test::evaluate(scene, final);
  test::report_final_figures(name, final_ate, ate);
  EXPECT_TRUE(log.lost_frames().empty()) << log.lost_frames().size() << " frames lost: " << list(log.lost_frames());
  EXPECT_LE(ate.ate_percent_of_path, max_percent);
  // Tracking must cover the sequence, not just a lucky part of it.
  EXPECT_EQ(log.tracked(), log.frames.size() - static_cast<std::size_t>(log.initialised_at()));
}

TEST(StreetRegression, StreetPanLosesNoFrameAndAteWithinOnePercent) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  expect_tracks_whole_street("street-pan", 1.0);
}

// The walk includes a 60-degree pure rotation (frames 465-525): tracked
// through it by keyframes taken when the camera turns and their depth-prior
// points (depth_prior_points.hpp).
TEST(StreetRegression, StreetWalkLosesNoFrameAndAteWithinOnePercent) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  expect_tracks_whole_street("street-walk", 1.0);
}

// KITTI's synthetic twin: a car at 9 m/s and 10 Hz, camera 1.65 m above the
// road looking forward, two 90-degree turns, parked cars, 1226x370 with
// KITTI's intrinsics (configs/scenes/street-drive.yaml). Issue 16: no frame
// lost after initialisation, ATE <= 0.5 % of the path. Run as `replay` runs
// it, with the shipped model's labels: its swaying trees are weighed down by
// the tracker, its parked and oncoming cars left out of tracking and bundle
// adjustment (LabelPolicy::moving). 0.046 % (online poses);
// without labels 0.019 %; with the tracker weighing cars down to 0.1 like
// the trees and bundle adjustment taking them at full weight (the earlier
// policy) 1.90 % (tracker seeds 2, 3: 1.01, 0.37 %).
TEST(StreetRegression, StreetDriveLosesNoFrameAndAteWithinHalfAPercent) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  SlamOptions options = test::synchronous_options();
  options.semantics.enabled = true;
  options.semantics.model = test::source_dir() / "models" / "default.fsmodel";
  expect_tracks_whole_street("street-drive", 0.5, options);
}

// kitti00-300's failure as a scene (configs/scenes/street-suburb.yaml): a
// wide street whose houses stand 22 m from its axis behind parked cars and
// hedges at the kerbs, the car accelerating to 12 m/s. The near things sweep
// out of view within frames; the houses ahead lie beyond the epipolar
// search's mean + 3 sigma and need a far partner for parallax. Without the
// far search (the landed settings) the map breaks down and about 80 frames
// are lost; with it, none.
TEST(StreetRegression, StreetSuburbLosesNoFrameAndAteWithinHalfAPercent) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  expect_tracks_whole_street("street-suburb", 0.5);
}

TEST(StreetRegression, StreetSuburbLosesFramesWithoutTheFarEpipolarSearch) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  SlamOptions options = test::synchronous_options();
  options.mapmaker.epipolar.min_far_depth_factor = 0.0;
  options.mapmaker.epipolar_partner.far_baseline = 0.0;
  test::SceneFrames scene(test::scene_file("street-suburb"));
  System system(scene.camera(), options);
  test::SlamRunLog log;
  test::run_frames(system, scene, 0, scene.size(), log);
  system.finish();
  std::printf("[  FIGURES ] street-suburb without the far epipolar search: %zu frames lost\n",
              log.lost_frames().size());
  EXPECT_GE(log.lost_frames().size(), 20u) << "the scene no longer reproduces the failure it was made for";
}

// Intensity scale, shift and colour temperature drifting over the walk: the
// zero-mean patch matching and the per-frame FAST thresholds must hold.
TEST(StreetRegression, StreetLightingLosesNoFrameAndAteWithinTwoPercent) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  expect_tracks_whole_street("street-lighting", 2.0);
}

// Ten frames replaced by black images while the camera keeps moving: the
// system must be tracking again within 10 frames of the real images
// returning, and lose nothing else.
TEST(StreetRegression, RelocalisesWithinTenFramesAfterTenBlackFrames) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  constexpr int kFirstBlack = 100, kBlackFrames = 10, kFrames = 180;
  test::SceneFrames scene(test::scene_file("street-pan"), kFrames);
  System system(scene.camera(), test::synchronous_options());
  test::SlamRunLog log;
  test::run_frames(system, scene, 0, scene.size(), log, [&](int i, cv::Mat image) {
    if (i >= kFirstBlack && i < kFirstBlack + kBlackFrames) image.setTo(cv::Scalar::all(0));
    return image;
  });
  ASSERT_TRUE(system.initialised());
  ASSERT_LT(log.initialised_at(), kFirstBlack);

  int back_at = -1;
  std::vector<std::size_t> lost_outside;
  for (const FrameReport& f : log.frames) {
    const int i = static_cast<int>(f.index);
    if (i <= log.initialised_at() || i < kFirstBlack + kBlackFrames) {
      if (i > log.initialised_at() && i < kFirstBlack && !f.has_pose) lost_outside.push_back(f.index);
      continue;
    }
    if (back_at < 0 && f.has_pose) back_at = i;
    if (back_at >= 0 && !f.has_pose) lost_outside.push_back(f.index);
  }
  const int delay = back_at < 0 ? -1 : back_at - (kFirstBlack + kBlackFrames);
  std::printf(
      "[  FIGURES ] forced loss: frames %d-%d black, tracking again at frame %d (%d frames after the real "
      "images returned)\n",
      kFirstBlack, kFirstBlack + kBlackFrames - 1, back_at, delay);
  ::testing::Test::RecordProperty("relocalisation_delay_frames", delay);
  ASSERT_GE(back_at, 0) << "never relocalised";
  EXPECT_LT(delay, 10);
  EXPECT_TRUE(lost_outside.empty()) << "lost outside the black frames: " << list(lost_outside);
  const TrajectoryEvaluation ate = test::evaluate(scene, log.estimate);
  test::report_figures("street-pan with 10 black frames", log, ate);
  EXPECT_LE(ate.ate_percent_of_path, 1.0);
}

// The map saved mid-sequence and loaded into a new system: tracking resumes
// (relocalising against the loaded keyframes) and continues in the same
// world frame to the end of the sequence.
TEST(StreetRegression, MapSavedMidSequenceKeepsTrackingInANewSystem) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  constexpr int kSplit = 150;
  test::SceneFrames scene(test::scene_file("street-pan"));
  test::TempDir dir;
  const fs::path map_file = dir / "map.fslmap";
  test::SlamRunLog first;
  std::size_t saved_keyframes = 0, saved_points = 0;
  {
    System system(scene.camera(), test::synchronous_options());
    test::run_frames(system, scene, 0, kSplit, first);
    ASSERT_TRUE(system.initialised());
    ASSERT_TRUE(first.lost_frames().empty()) << list(first.lost_frames());
    save_map(map_file, system.map(), system.camera());
    saved_keyframes = system.map().keyframe_count();
    saved_points = system.map().point_count();
  }

  System system(scene.camera(), test::synchronous_options());
  system.load_map(map_file);
  EXPECT_EQ(system.map().keyframe_count(), saved_keyframes);
  EXPECT_EQ(system.map().point_count(), saved_points);
  test::SlamRunLog second;
  test::run_frames(system, scene, kSplit, scene.size(), second);
  system.finish();

  int resumed_at = -1;
  for (const FrameReport& f : second.frames)
    if (f.has_pose) {
      resumed_at = static_cast<int>(f.index);
      break;
    }
  std::printf(
      "[  FIGURES ] save/load: map of %zu keyframes, %zu points saved at frame %d; the new system tracks "
      "from frame %d\n",
      saved_keyframes, saved_points, kSplit, resumed_at);
  ASSERT_GE(resumed_at, 0) << "the new system never localised against the loaded map";
  EXPECT_LT(resumed_at, kSplit + 10);
  EXPECT_TRUE(second.lost_frames().empty()) << "lost after resuming: " << list(second.lost_frames());

  // Both runs together, one Sim(3): the loaded map kept the world frame and scale.
  test::SlamRunLog both = first;
  both.frames.insert(both.frames.end(), second.frames.begin(), second.frames.end());
  both.estimate.insert(both.estimate.end(), second.estimate.begin(), second.estimate.end());
  both.tracker_ms.insert(both.tracker_ms.end(), second.tracker_ms.begin(), second.tracker_ms.end());
  const TrajectoryEvaluation ate = test::evaluate(scene, both.estimate);
  test::report_figures("street-pan saved and reloaded", both, ate);
  EXPECT_LE(ate.ate_percent_of_path, 1.0);
}

}  // namespace
}  // namespace facadeslam
