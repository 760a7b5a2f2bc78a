#include "tests/slam/slam_test_run.hpp"

#include <algorithm>
#include <cstdio>

#include <gtest/gtest.h>

#include "sequences/synth/scene_loader.hpp"
#include "tests/support/test_support.hpp"

namespace facadeslam::test {

SceneFrames::SceneFrames(const std::filesystem::path& scene_file, int frames) : spec_(synth::load_scene(scene_file)) {
  if (frames > 0) spec_.frames = std::min(spec_.frames, frames);
  synthesizer_ = std::make_unique<synth::FrameSynthesizer>(spec_);
  for (int i = 0; i < spec_.frames; ++i)
    ground_truth_.push_back({synthesizer_->timestamp(i), synthesizer_->path().T_w_c(synthesizer_->timestamp(i))});
}

int SlamRunLog::initialised_at() const {
  for (const FrameReport& f : frames)
    if (f.status == FrameStatus::initialised) return static_cast<int>(f.index);
  return -1;
}

std::vector<std::size_t> SlamRunLog::lost_frames() const {
  std::vector<std::size_t> lost;
  bool started = false;
  for (const FrameReport& f : frames) {
    started = started || f.has_pose;
    if (started && !f.has_pose) lost.push_back(f.index);
  }
  return lost;
}

std::size_t SlamRunLog::tracked() const {
  return static_cast<std::size_t>(
      std::count_if(frames.begin(), frames.end(), [](const FrameReport& f) { return f.has_pose; }));
}

namespace {

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())))];
}

}  // namespace

void SlamRunLog::add(FrameReport report) {
  if (report.initial_reference) estimate.push_back({report.initial_reference->second, Eigen::Isometry3d::Identity()});
  if (report.has_pose) estimate.push_back({report.timestamp, report.T_c_w.inverse().isometry()});
  if (report.status == FrameStatus::tracking || report.status == FrameStatus::relocalised) {
    const StageTimings& t = report.tracking.timings;
    tracker_ms.push_back(report.pyramid_ms + t.coarse_ms + t.fine_ms + t.pose_ms + t.relocalise_ms);
  }
  frames.push_back(std::move(report));
}

double SlamRunLog::tracker_ms_median() const { return percentile(tracker_ms, 0.5); }
double SlamRunLog::tracker_ms_p95() const { return percentile(tracker_ms, 0.95); }

std::filesystem::path scene_file(const std::string& name) {
  return source_dir() / "configs" / "scenes" / (name + ".yaml");
}

cv::Mat SceneFrames::render(int index) {
  synth::SynthFrame frame = synthesizer_->render(index);
  if (keep_labels_) labels_[static_cast<std::size_t>(index)] = frame.labels;
  return frame.colour;
}

cv::Mat SceneFrames::labels(std::size_t index) const {
  const auto it = labels_.find(index);
  return it == labels_.end() ? cv::Mat() : it->second;
}

void run_frames(System& system, SceneFrames& scene, int first, int last, SlamRunLog& log, const FrameFilter& filter) {
  for (int i = first; i < last; ++i) {
    cv::Mat image = scene.render(i);
    if (filter) image = filter(i, std::move(image));
    log.add(system.process({static_cast<std::size_t>(i), scene.timestamp(i), image}));
  }
}

TrajectoryEvaluation evaluate(const SceneFrames& scene, const Trajectory& estimate) {
  return evaluate_trajectory(scene.ground_truth(), estimate, {});
}

void report_figures(const std::string& name, const SlamRunLog& log, const TrajectoryEvaluation& ate) {
  std::printf(
      "[  FIGURES ] %s: %zu frames, initialised at frame %d, %zu tracked, %zu lost after initialisation, "
      "ATE (Sim3) %.4f m = %.3f %% of the %.2f m path, tracker %.2f ms median / %.2f ms p95 per frame\n",
      name.c_str(), log.frames.size(), log.initialised_at(), log.tracked(), log.lost_frames().size(), ate.ate_rmse_m,
      ate.ate_percent_of_path, ate.path_length_m, log.tracker_ms_median(), log.tracker_ms_p95());
  std::fflush(stdout);
  ::testing::Test::RecordProperty("frames", static_cast<int>(log.frames.size()));
  ::testing::Test::RecordProperty("initialised_at", log.initialised_at());
  ::testing::Test::RecordProperty("tracked", static_cast<int>(log.tracked()));
  ::testing::Test::RecordProperty("lost", static_cast<int>(log.lost_frames().size()));
  ::testing::Test::RecordProperty("ate_rmse_m", std::to_string(ate.ate_rmse_m));
  ::testing::Test::RecordProperty("ate_percent_of_path", std::to_string(ate.ate_percent_of_path));
  ::testing::Test::RecordProperty("path_length_m", std::to_string(ate.path_length_m));
  ::testing::Test::RecordProperty("tracker_ms_median", std::to_string(log.tracker_ms_median()));
  ::testing::Test::RecordProperty("tracker_ms_p95", std::to_string(log.tracker_ms_p95()));
}

void report_final_figures(const std::string& name, const TrajectoryEvaluation& final_ate,
                          const TrajectoryEvaluation& online_ate) {
  std::printf(
      "[  FIGURES ] %s: final trajectory (recomposed from the final map) ATE (Sim3) %.4f m = %.3f %% of the "
      "%.2f m path; as tracked %.3f %%\n",
      name.c_str(), final_ate.ate_rmse_m, final_ate.ate_percent_of_path, final_ate.path_length_m,
      online_ate.ate_percent_of_path);
  std::fflush(stdout);
  ::testing::Test::RecordProperty("final_ate_rmse_m", std::to_string(final_ate.ate_rmse_m));
  ::testing::Test::RecordProperty("final_ate_percent_of_path", std::to_string(final_ate.ate_percent_of_path));
}

SlamOptions synchronous_options() {
  SlamOptions options;
  options.synchronous = true;
  return options;
}

}  // namespace facadeslam::test
