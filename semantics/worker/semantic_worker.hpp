#pragma once
// The semantic worker, the third thread: takes each keyframe's newly measured
// points from the map maker (KeyFramePointsQueue), computes the model's
// descriptor where the keyframe saw each point in its colour image (the
// genome's per-image planes once per keyframe), classifies it with the forest
// and adds the forest's per-class vote shares to the point's vote sums: a
// point seen by several keyframes gets the fused label of all its views (the
// arg-max, with the winner's share as confidence). Labels are atomics in
// MapPoint: the tracker is never blocked.
//
// Two ways to run it, as the map maker: a thread (start/stop) waiting on the
// queue, or process_pending() called inline after the map maker (--sync),
// which makes runs bit-reproducible. The thread runs at the lowest CPU
// priority: where the cores are busy it yields them to the tracker.
#include <memory>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "core/map/keyframe_points.hpp"
#include "core/map/map.hpp"
#include "semantics/forest/forest_model.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"
#include "semantics/worker/moving_regions.hpp"
#include "semantics/worker/neighbour_label_fusion.hpp"

namespace facadeslam::semantics {

struct SemanticWorkerStats {
  std::size_t keyframes = 0;              // jobs done
  std::size_t observations_labelled = 0;  // votes added (a point gets one per keyframe measuring it)
  std::size_t observations_skipped = 0;   // bad by the time they came, or no colour image
  std::vector<double> keyframe_ms;        // per job
  std::size_t grey_keyframes = 0;         // jobs whose keyframe image was grey
  bool grey_model = false;                // ... labelled by the grey model (else left unlabelled)
};

// Whether a BGR image is grey (its three channels equal, sampled).
bool is_grey(const cv::Mat& bgr);

class SemanticWorker {
 public:
  // `class_weights` multiply each observation's vote shares (then scaled to
  // sum to 1) before they are fused: a prior on how common each class is
  // (SemanticsOptions::class_weights). All ones: the forest's votes.
  SemanticWorker(ForestModel model, KeyFramePointsQueue& queue, const ClassVotes& class_weights = all_ones());
  static ClassVotes all_ones();
  // A model trained on grey photos (`train --grey`) for grey keyframes (a grey
  // camera such as KITTI's): without one their points stay unlabelled, as the
  // colour model, shown grey, calls a third of a street sky. Call before
  // start(). Throws Error if its descriptor does not fit its forest.
  void use_grey_model(ForestModel model);
  // Also classify each point in the keyframe shrunk by `scale` (0 < scale < 1;
  // 0 = not) and add those votes to the full-size ones: the descriptor's patch
  // then covers 1/scale times more of the facade around the point, context a
  // 21-pixel patch at a window's corner does not have. Call before start().
  void use_context_scale(double scale);
  // Also detect regions of `moving_classes` (moving_regions.hpp) in each
  // keyframe and tell each point whether it lay in one
  // (MapPoint::add_region_view). Call before start(); throws Error for
  // options out of range. step 0 or no moving class: no detection (the
  // default).
  void use_moving_regions(const MovingRegionOptions& options, const ClassSet& moving_classes);
  // After each round of keyframes, give every labelled point of `map` the
  // label of its votes fused with its nearest points' and the geometric cue
  // (neighbour_label_fusion.hpp). Call before start(); `map` must outlive
  // the worker.
  void use_map_labels(const Map& map, const MapLabelOptions& options);
  ~SemanticWorker();
  SemanticWorker(const SemanticWorker&) = delete;
  SemanticWorker& operator=(const SemanticWorker&) = delete;

  // Synchronous mode: labels everything queued.
  void process_pending();

  // Threaded mode. stop() closes the queue, labels what is left, joins.
  void start();
  void stop();

  SemanticWorkerStats stats() const;

  // Labels one keyframe's points now (the unit of work; public for tests).
  // The neighbour fusion follows once the queue is drained (fuse()).
  void label(const KeyFramePoints& job);
  void fuse();

 private:
  void run();
  static constexpr int kWorkerNice = 19;  // see run()

  // A forest and the descriptor it was trained on.
  struct Classifier {
    ForestModel model;
    std::unique_ptr<PointDescriptor> descriptor;
  };
  static Classifier make_classifier(ForestModel model);
  // The forest's vote shares (one row per keypoint, one column per forest
  // class) for the descriptor at `keypoints` in `image` shrunk by `scale`.
  static cv::Mat vote_shares(const Classifier& classifier, const cv::Mat& image,
                             const std::vector<cv::Point2f>& keypoints, double scale);

  Classifier colour_;
  std::optional<Classifier> grey_;
  ClassVotes class_weights_;
  double context_scale_ = 0.0;
  MovingRegionOptions region_options_{.step = 0};
  ClassSet moving_classes_;
  const Map* fusion_map_ = nullptr;
  MapLabelOptions fusion_options_{.neighbours = 0, .sky_only_at_infinity = false};
  KeyFramePointsQueue& queue_;
  std::thread thread_;
  mutable std::mutex stats_mutex_;
  SemanticWorkerStats stats_;
};

}  // namespace facadeslam::semantics
