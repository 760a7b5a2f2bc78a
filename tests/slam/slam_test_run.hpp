#pragma once
// Running the SLAM system over a synthetic scene in a test: the scene is
// rendered frame by frame in memory (the same images `facadeslam synth`
// writes, PNG being lossless) and fed to a synchronous System, and the run's
// figures are collected for the assertions and the report.
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include <opencv2/core.hpp>

#include "core/trajectory/metrics.hpp"
#include "core/trajectory/trajectory.hpp"
#include "sequences/synth/frame_synthesizer.hpp"
#include "sequences/synth/scene.hpp"
#include "slam/system.hpp"

namespace facadeslam::test {

// configs/scenes/NAME.yaml in the source tree.
std::filesystem::path scene_file(const std::string& name);

// A scene file's frames, rendered on demand.
class SceneFrames {
 public:
  // `frames` > 0 renders only the first `frames` frames of the scene.
  explicit SceneFrames(const std::filesystem::path& scene_file, int frames = 0);
  int size() const { return spec_.frames; }
  const Camera& camera() const { return spec_.camera; }
  double timestamp(int index) const { return synthesizer_->timestamp(index); }
  // The colour image; with keep_labels(), its label image is kept too.
  cv::Mat render(int index);
  void keep_labels() { keep_labels_ = true; }
  // Class ids (CV_8UC1) of a frame rendered since keep_labels(), else empty.
  cv::Mat labels(std::size_t index) const;
  // Every frame's true camera-to-world pose.
  const Trajectory& ground_truth() const { return ground_truth_; }

 private:
  synth::SceneSpec spec_;
  std::unique_ptr<synth::FrameSynthesizer> synthesizer_;
  Trajectory ground_truth_;
  bool keep_labels_ = false;
  std::map<std::size_t, cv::Mat> labels_;
};

// What happened to each frame of a run, and the figures the issue asks for.
struct SlamRunLog {
  std::vector<FrameReport> frames;  // in processing order
  Trajectory estimate;              // camera-to-world of the frames with a pose
  std::vector<double> tracker_ms;   // pyramid + FAST + coarse + fine + pose (+ relocalisation) per tracked frame

  // Records one processed frame (its pose, if any, and its tracker time).
  void add(FrameReport report);

  // Index of the frame the map was initialised at, or -1.
  int initialised_at() const;
  // Frames after initialisation (or after the first pose, for a loaded map)
  // without a pose.
  std::vector<std::size_t> lost_frames() const;
  std::size_t tracked() const;
  double tracker_ms_median() const;
  double tracker_ms_p95() const;
};

// Which image the system gets for frame i (to black out frames, say).
using FrameFilter = std::function<cv::Mat(int index, cv::Mat rendered)>;

// Feeds frames [first, last) to `system` and logs them (appends to `log`).
void run_frames(System& system, SceneFrames& scene, int first, int last, SlamRunLog& log,
                const FrameFilter& filter = {});

// Sim(3)-aligned ATE of `estimate` against the scene's ground truth.
TrajectoryEvaluation evaluate(const SceneFrames& scene, const Trajectory& estimate);

// One line of figures on stdout (ctest -V / the test log) and as test
// properties (gtest XML): name, frames, initialisation frame, tracked, lost,
// ATE, path, tracker ms median and p95.
void report_figures(const std::string& name, const SlamRunLog& log, const TrajectoryEvaluation& ate);

// One line of the final trajectory's figures (System::final_trajectory,
// what trajectory.txt holds) beside the online ones, and as test properties
// (final_ate_rmse_m, final_ate_percent_of_path).
void report_final_figures(const std::string& name, const TrajectoryEvaluation& final_ate,
                          const TrajectoryEvaluation& online_ate);

// The synchronous System the regression runs use (fixed seed: the default).
SlamOptions synchronous_options();

}  // namespace facadeslam::test
