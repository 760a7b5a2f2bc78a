#include "semantics/worker/semantic_worker.hpp"

#include <algorithm>
#include <cerrno>
#include <system_error>

#include <sys/resource.h>
#include <unistd.h>

#include <opencv2/imgproc.hpp>
#include <spdlog/spdlog.h>

#include "core/util/error.hpp"
#include "core/util/stopwatch.hpp"
#include "semantics/point_descriptors/forest_votes.hpp"

namespace facadeslam::semantics {

ClassVotes SemanticWorker::all_ones() {
  ClassVotes ones;
  ones.fill(1.f);
  return ones;
}

bool is_grey(const cv::Mat& bgr) {
  // Every 7th pixel of every 7th row: enough to tell, cheap beside the descriptor.
  for (int y = 0; y < bgr.rows; y += 7) {
    const auto* row = bgr.ptr<cv::Vec3b>(y);
    for (int x = 0; x < bgr.cols; x += 7)
      if (row[x][0] != row[x][1] || row[x][1] != row[x][2]) return false;
  }
  return true;
}

SemanticWorker::Classifier SemanticWorker::make_classifier(ForestModel model) {
  Classifier c{std::move(model), nullptr};
  c.descriptor = make_point_descriptor(c.model.descriptor, c.model.genome);
  if (c.descriptor->width() != c.model.descriptor_width())
    throw Error("semantic worker: the model's forest takes " + std::to_string(c.model.descriptor_width()) +
                " values, its descriptor gives " + std::to_string(c.descriptor->width()));
  return c;
}

SemanticWorker::SemanticWorker(ForestModel model, KeyFramePointsQueue& queue, const ClassVotes& class_weights)
    : colour_(make_classifier(std::move(model))), class_weights_(class_weights), queue_(queue) {}

void SemanticWorker::use_grey_model(ForestModel model) {
  grey_ = make_classifier(std::move(model));
  std::lock_guard lock(stats_mutex_);
  stats_.grey_model = true;
}

void SemanticWorker::use_context_scale(double scale) {
  if (!(scale >= 0.0 && scale < 1.0))
    throw Error("semantic worker: a context scale in [0, 1) (0 = none), not " + std::to_string(scale));
  context_scale_ = scale;
}

void SemanticWorker::use_moving_regions(const MovingRegionOptions& options, const ClassSet& moving_classes) {
  // Checked here, before any keyframe comes.
  if (options.step > 0) MovingRegions::check(options);
  region_options_ = options;
  moving_classes_ = moving_classes;
}

void SemanticWorker::use_map_labels(const Map& map, const MapLabelOptions& options) {
  if (options.neighbours < 0)
    throw Error("semantic worker: a number of neighbours >= 0 (0 = none), not " + std::to_string(options.neighbours));
  fusion_map_ = &map;
  fusion_options_ = options;
}

SemanticWorker::~SemanticWorker() { stop(); }

cv::Mat SemanticWorker::vote_shares(const Classifier& classifier, const cv::Mat& image,
                                    const std::vector<cv::Point2f>& keypoints, double scale) {
  return forest_vote_shares(*classifier.descriptor, classifier.model.forest, image, keypoints, scale);
}

void SemanticWorker::label(const KeyFramePoints& job) {
  const Stopwatch watch;
  std::vector<std::shared_ptr<MapPoint>> points;
  std::vector<cv::Point2f> keypoints;
  const cv::Mat& colour = job.keyframe->colour();
  // The colour image may be missing, or grey in three channels (a grey
  // sequence such as KITTI's, decoded to BGR): the colour forest learnt its
  // classes from colour photographs, and on grey it calls a third of a street
  // sky. Grey keyframes go to the grey model; without one their points stay
  // unlabelled, counted as grey.
  const bool grey = !colour.empty() && colour.type() == CV_8UC3 && is_grey(colour);
  const Classifier* classifier = grey ? (grey_ ? &*grey_ : nullptr) : &colour_;
  const bool describable = !colour.empty() && colour.type() == CV_8UC3 && classifier != nullptr;
  std::size_t skipped = 0;
  for (const PointMeasurement& seen : job.points) {
    // A point the map maker has dropped since the hand-off gets no votes.
    if (!describable || seen.point->is_bad()) {
      ++skipped;
      continue;
    }
    keypoints.emplace_back(static_cast<float>(std::clamp(seen.pixel.x(), 0.0, colour.cols - 1.0)),
                           static_cast<float>(std::clamp(seen.pixel.y(), 0.0, colour.rows - 1.0)));
    points.push_back(seen.point);
  }
  if (!points.empty()) {
    // The moving-region grid's cells go through the descriptor with the
    // points: its planes are computed once per image. Not on grey keyframes:
    // the grey model's car calls are too poor for regions (kitti00-300: its
    // regions over hedges and parked cars left 50-120 points a frame out and
    // tracking failed after the second turn, 77 % of the frames tracked, ATE
    // 8 %; without them 298 of 298, 1.2 %, as with semantics off).
    std::optional<MovingRegions> regions;
    if (region_options_.step > 0 && moving_classes_.any() && !grey) {
      regions.emplace(colour.size(), region_options_);
      keypoints.insert(keypoints.end(), regions->cells().begin(), regions->cells().end());
    }
    cv::Mat shares = vote_shares(*classifier, colour, keypoints, 1.0);
    if (context_scale_ > 0.0) shares += vote_shares(*classifier, colour, keypoints, context_scale_);
    const std::vector<int>& columns = classifier->model.forest.classes();
    if (regions) {
      const auto first_cell = static_cast<int>(points.size());
      regions->set_calls(shares.rowRange(first_cell, shares.rows), columns, class_weights_, moving_classes_);
    }
    for (std::size_t i = 0; i < points.size(); ++i) {
      if (regions) points[i]->add_region_view(regions->contains(keypoints[i]));
      ClassVotes votes{};
      float total = 0.f;
      for (std::size_t k = 0; k < columns.size(); ++k) {
        const auto c = static_cast<std::size_t>(columns[k]);
        votes[c] = shares.at<float>(static_cast<int>(i), static_cast<int>(k)) * class_weights_[c];
        total += votes[c];
      }
      // One observation, one vote: shares scaled back to sum to 1.
      if (!(total > 0.f)) continue;
      for (float& v : votes) v /= total;
      points[i]->add_votes(votes);
    }
  }
  std::lock_guard lock(stats_mutex_);
  ++stats_.keyframes;
  stats_.grey_keyframes += grey;
  stats_.observations_labelled += points.size();
  stats_.observations_skipped += skipped;
  stats_.keyframe_ms.push_back(watch.elapsed_ms());
}

void SemanticWorker::fuse() {
  if (fusion_map_ == nullptr || (fusion_options_.neighbours == 0 && !fusion_options_.sky_only_at_infinity)) return;
  const Stopwatch watch;
  fuse_labels_with_neighbours(*fusion_map_, fusion_options_);
  // Part of the last keyframe's work in the figures.
  std::lock_guard lock(stats_mutex_);
  if (!stats_.keyframe_ms.empty()) stats_.keyframe_ms.back() += watch.elapsed_ms();
}

void SemanticWorker::process_pending() {
  bool labelled = false;
  while (auto job = queue_.try_pop()) {
    label(*job);
    labelled = true;
  }
  if (labelled) fuse();
}

void SemanticWorker::start() {
  if (thread_.joinable()) return;
  thread_ = std::thread([this] { run(); });
}

void SemanticWorker::stop() {
  queue_.close();
  if (thread_.joinable()) thread_.join();
}

void SemanticWorker::run() {
  // Labels are a background refinement, the tracker is the real-time thread:
  // the worker runs at the lowest CPU priority (nice 19, this thread only),
  // so that where the cores are busy it takes the time the tracker and the
  // map maker leave. At nice 0 the tracker's median frame time on the demo
  // was 5-13 % above its time without the worker (two cores, bench
  // BM_ReplayThreadedSemantics), at nice 19 within 1 %. Its jobs wait in the
  // queue meanwhile; a point's labels come a little later.
  if (setpriority(PRIO_PROCESS, static_cast<id_t>(gettid()), kWorkerNice) != 0)
    spdlog::debug("semantic worker: could not lower its priority ({})", std::generic_category().message(errno));
  for (;;) {
    queue_.wait_until([] { return false; });
    if (auto job = queue_.try_pop()) {
      label(*job);
      if (queue_.empty()) fuse();  // a backlog is fused once, after its last keyframe
      continue;
    }
    if (queue_.closed()) break;
  }
}

SemanticWorkerStats SemanticWorker::stats() const {
  std::lock_guard lock(stats_mutex_);
  return stats_;
}

}  // namespace facadeslam::semantics
