#pragma once
// The semantic worker, the third thread: takes each keyframe's new points
// from the map maker (KeyFramePointsQueue), computes the model's descriptor
// at every point's patch centre in the keyframe's colour image (the genome's
// per-image planes once per keyframe), classifies it with the forest and
// writes label + confidence (the winning class's vote share) into the point.
// Labels are atomics in MapPoint: the tracker is never blocked.
//
// Two ways to run it, as the map maker: a thread (start/stop) waiting on the
// queue, or process_pending() called inline after the map maker (--sync),
// which makes runs bit-reproducible.
#include <memory>
#include <mutex>
#include <thread>
#include <vector>

#include "core/map/keyframe_points.hpp"
#include "semantics/forest/forest_model.hpp"
#include "semantics/point_descriptors/point_descriptor.hpp"

namespace facadeslam::semantics {

struct SemanticWorkerStats {
  std::size_t keyframes = 0;          // jobs done
  std::size_t points_labelled = 0;
  std::size_t points_skipped = 0;     // bad by the time they came, or no colour image
  std::vector<double> keyframe_ms;    // per job
};

class SemanticWorker {
 public:
  SemanticWorker(ForestModel model, KeyFramePointsQueue& queue);
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
  void label(const KeyFramePoints& job);

 private:
  void run();

  ForestModel model_;
  std::unique_ptr<PointDescriptor> descriptor_;
  KeyFramePointsQueue& queue_;
  std::thread thread_;
  mutable std::mutex stats_mutex_;
  SemanticWorkerStats stats_;
};

}  // namespace facadeslam::semantics
