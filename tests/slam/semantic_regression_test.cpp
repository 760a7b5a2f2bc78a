// Issue 17's regression runs: the three-thread system in synchronous mode
// (reproducible bit for bit) with the shipped model, on the synthetic
// streets, whose renderer gives every frame's true labels. Needs
// ../shared/data; prints its figures ("[  FIGURES ]" lines).
#include <cmath>
#include <map>
#include <set>

#include <gtest/gtest.h>

#include "semantics/evaluation/map_label_accuracy.hpp"
#include "tests/slam/slam_test_run.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam {
namespace {

namespace fs = std::filesystem;

SlamOptions options_with_semantics(bool on) {
  SlamOptions options = test::synchronous_options();
  options.semantics.enabled = on;
  options.semantics.model = test::source_dir() / "models" / "default.fsmodel";
  return options;
}

struct SemanticRun {
  test::SlamRunLog log;
  TrajectoryEvaluation ate;
  semantics::MapLabelAccuracy labels;
  std::size_t points = 0, dropped = 0;  // dropped: left out or down-weighted, over the frames
};

SemanticRun run_scene(const std::string& name, bool semantics_on) {
  test::SceneFrames scene(test::scene_file(name));
  scene.keep_labels();
  System system(scene.camera(), options_with_semantics(semantics_on));
  SemanticRun run;
  test::run_frames(system, scene, 0, scene.size(), run.log);
  system.finish();
  EXPECT_TRUE(system.initialised());
  run.ate = test::evaluate(scene, run.log.estimate);
  run.labels = semantics::map_label_accuracy(system.map(), [&](std::size_t i) { return scene.labels(i); });
  run.points = system.map().point_count();
  for (const FrameReport& f : run.log.frames)
    run.dropped += static_cast<std::size_t>(f.tracking.points_dropped + f.tracking.points_down_weighted);
  test::report_figures(name + (semantics_on ? ", semantics on" : ", semantics off"), run.log, run.ate);
  if (semantics_on) {
    std::printf(
        "[  FIGURES ] %s labels: %zu of %zu points labelled, label accuracy %.3f over %zu points; per true "
        "class:",
        name.c_str(), run.points - run.labels.unlabelled, run.points, run.labels.accuracy().value_or(0.0),
        run.labels.evaluated);
    for (const SemanticClass& c : kSemanticClasses)
      if (const auto share = run.labels.class_accuracy(c.id))
        std::printf(" %s %.2f (%zu)", std::string(c.name).c_str(), *share, run.labels.per_class_points[c.id]);
    std::printf("; %zu measurements left out or down-weighted for their class\n", run.dropped);
    std::printf("[  FIGURES ] %s labels, commonest mistake per true class:", name.c_str());
    for (const SemanticClass& c : kSemanticClasses)
      if (const auto mistake = run.labels.commonest_mistake(c.id))
        std::printf(" %s -> %s (%zu)", std::string(c.name).c_str(),
                    std::string(kSemanticClasses[mistake->first].name).c_str(), mistake->second);
    std::printf("\n");
  }
  std::fflush(stdout);
  return run;
}

// The walk with labels: nearly every point labelled, most of them right, and
// tracking as good as ever. The issue asks for a label accuracy of 0.70; the
// shipped forest with view fusion, the class prior, the context of the
// keyframe shrunk to a quarter and each label fused with its 15 nearest map
// points' gives 0.713 here (without the neighbours 0.674, without the context
// 0.635; views alone 0.43, the full prior 0.69 with no window or door left:
// windows are the forest's weak class, 12 % precision on LabelMeFacade
// itself). The figure moves with the map (how many of its points are
// windows, all of them wrong): over the tracker's sampling seeds 1-3 it is
// 0.702-0.714 (0.671-0.676 without the neighbours), so the 0.70 holds
// on each map, by a little; the map's 'no sky on triangulated points' cue
// moves it by 0.001 at most (its 13 right sky points are roofline corners).
// Windows stay at 0.00 (NOTES.md).
TEST(SemanticRegression, StreetWalkIsLabelledAndStillTrackedWithinPointThreePercent) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  const SemanticRun run = run_scene("street-walk", true);
  ASSERT_GT(run.points, 0u);
  EXPECT_GE(static_cast<double>(run.points - run.labels.unlabelled), 0.9 * static_cast<double>(run.points));
  ASSERT_TRUE(run.labels.accuracy().has_value());
  EXPECT_GE(*run.labels.accuracy(), 0.70);
  EXPECT_TRUE(run.log.lost_frames().empty());
  EXPECT_LE(run.ate.ate_percent_of_path, 0.3);
}

// Cars drive through the street and trees sway: weighing their points down
// must make the trajectory better.
TEST(SemanticRegression, StreetDynamicTracksBetterWithLabels) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  const SemanticRun off = run_scene("street-dynamic", false);
  const SemanticRun on = run_scene("street-dynamic", true);
  std::printf("[  FIGURES ] street-dynamic: ATE %.3f %% with labels, %.3f %% without (ratio %.2f)\n",
              on.ate.ate_percent_of_path, off.ate.ate_percent_of_path,
              on.ate.ate_percent_of_path / off.ate.ate_percent_of_path);
  EXPECT_GT(on.dropped, 0u) << "label-aware tracking never weighed a point down";
  EXPECT_TRUE(on.log.lost_frames().empty());
  EXPECT_LE(on.ate.ate_percent_of_path, 0.85 * off.ate.ate_percent_of_path);
}

// A perfect classifier, for the test of what labels are for: every new map
// point gets the renderer's true class at its pixel in its source keyframe as
// an overwhelming vote (in --sync mode nothing else writes votes meanwhile).
class TrueLabeller {
 public:
  void label_new_points(const Map& map, const test::SceneFrames& scene) {
    std::map<KeyFrame::Id, std::size_t> frame_of;
    for (const KeyFrameSnapshot& kf : map.snapshot_keyframes())
      frame_of[kf.keyframe->id()] = kf.keyframe->frame_index();
    for (const PointSnapshot& p : map.snapshot_points()) {
      const auto frame = frame_of.find(p.source.keyframe_id);
      if (frame == frame_of.end() || !labelled_.insert(p.point->id()).second) continue;
      const cv::Mat truth = scene.labels(frame->second);
      const int x = static_cast<int>(std::lround(p.source.pixel_level0.x()));
      const int y = static_cast<int>(std::lround(p.source.pixel_level0.y()));
      ASSERT_TRUE(x >= 0 && y >= 0 && x < truth.cols && y < truth.rows);
      // A pixel of no class: a perfect classifier has no label to give either.
      const auto true_class = semantics::true_class_at(truth, p.source.pixel_level0);
      if (!true_class) continue;
      ClassVotes votes{};
      votes[*true_class] = 1e6f;
      p.point->add_votes(votes);
    }
  }

 private:
  std::set<std::size_t> labelled_;
};

SemanticRun run_with_true_labels(const std::string& name) {
  test::SceneFrames scene(test::scene_file(name));
  scene.keep_labels();
  SlamOptions options = options_with_semantics(true);
  // True labels need no neighbours' votes (and the labeller's overwhelming
  // votes would count as one point's shares among them), nor the forest's
  // moving regions.
  options.semantics.label_neighbours = 0;
  options.semantics.moving_regions.step = 0;
  System system(scene.camera(), options);
  TrueLabeller labeller;
  SemanticRun run;
  for (int i = 0; i < scene.size(); ++i) {
    run.log.add(system.process({static_cast<std::size_t>(i), scene.timestamp(i), scene.render(i)}));
    labeller.label_new_points(system.map(), scene);
  }
  system.finish();
  run.ate = test::evaluate(scene, run.log.estimate);
  run.points = system.map().point_count();
  test::report_figures(name + ", true labels", run.log, run.ate);
  return run;
}

// Traffic that fills the view: cars driving beside the walker at its own
// pace pull a label-blind tracker off (the scene must prove that: >= 2x its
// static twin, the same street and path with nothing moving). The issue asks
// that the labels bring it back to <= 1.2x the twin. The forest calls few of
// these close-up car points car one by one (20 % of the found ones by their
// own votes, 1.3 % with a confidence of 0.5: 8.70 % with its labels alone),
// but their regions are full of its car calls: with the moving regions
// (semantics/worker/moving_regions.hpp) 0.23 % against the twin's 0.30 %
// (other renders of the scene, seeds 2 and 3: 1.6x and 1.3x their twins').
// A perfect classifier (the renderer's true labels, no regions) shows what
// the settings can do: cars left out of tracking and bundle adjustment, the
// other unreliable classes weighed down to 0.1, 0.25 % (with cars weighed
// down to 0.1 like the rest 2.8-8.6 %: cars keeping pace look still, so even
// a small weight lets them steer; docs/benchmarks.md, sessions 24 and 25).
TEST(SemanticRegression, StreetTrafficPullsTheTrackerOffAndLabelsBringItBack) {
  FACADESLAM_REQUIRE_SHARED_DATA("labelmefacade");
  const SemanticRun twin = run_scene("street-traffic-static", false);
  const SemanticRun off = run_scene("street-traffic", false);
  const SemanticRun on = run_scene("street-traffic", true);
  const SemanticRun truth = run_with_true_labels("street-traffic");
  std::printf(
      "[  FIGURES ] street-traffic: ATE %.3f %% with the forest's labels, %.3f %% with true labels, "
      "%.3f %% without labels, static twin %.3f %%; lost %zu / %zu / %zu; map points %zu / %zu / %zu / %zu\n",
      on.ate.ate_percent_of_path, truth.ate.ate_percent_of_path, off.ate.ate_percent_of_path,
      twin.ate.ate_percent_of_path, on.log.lost_frames().size(), truth.log.lost_frames().size(),
      off.log.lost_frames().size(), on.points, truth.points, off.points, twin.points);
  EXPECT_TRUE(twin.log.lost_frames().empty());
  EXPECT_GE(off.ate.ate_percent_of_path, 2.0 * twin.ate.ate_percent_of_path);
  EXPECT_TRUE(truth.log.lost_frames().empty());
  EXPECT_LE(truth.ate.ate_percent_of_path, 1.2 * twin.ate.ate_percent_of_path);
  EXPECT_TRUE(on.log.lost_frames().empty());
  EXPECT_GT(on.dropped, 0u) << "label-aware tracking never weighed a car point down";
  EXPECT_LE(on.ate.ate_percent_of_path, 1.2 * twin.ate.ate_percent_of_path);
}

}  // namespace
}  // namespace facadeslam
