#include "semantics/worker/semantic_worker.hpp"

#include <algorithm>

#include "core/util/error.hpp"
#include "core/util/stopwatch.hpp"

namespace facadeslam::semantics {

SemanticWorker::SemanticWorker(ForestModel model, KeyFramePointsQueue& queue)
    : model_(std::move(model)), descriptor_(make_point_descriptor(model_.descriptor, model_.genome)), queue_(queue) {
  if (descriptor_->width() != model_.descriptor_width())
    throw Error("semantic worker: the model's forest takes " + std::to_string(model_.descriptor_width()) +
                " values, its descriptor gives " + std::to_string(descriptor_->width()));
}

SemanticWorker::~SemanticWorker() { stop(); }

void SemanticWorker::label(const KeyFramePoints& job) {
  const Stopwatch watch;
  std::vector<std::shared_ptr<MapPoint>> points;
  std::vector<cv::Point2f> keypoints;
  const cv::Mat& colour = job.keyframe->colour();
  // The colour image may be missing (a grey sequence): nothing to describe.
  const bool describable = !colour.empty() && colour.type() == CV_8UC3;
  std::size_t skipped = 0;
  for (const auto& p : job.points) {
    if (!describable || p->is_bad()) {
      ++skipped;
      continue;
    }
    const Eigen::Vector2d& px = p->source().pixel_level0;
    keypoints.emplace_back(static_cast<float>(std::clamp(px.x(), 0.0, colour.cols - 1.0)),
                           static_cast<float>(std::clamp(px.y(), 0.0, colour.rows - 1.0)));
    points.push_back(p);
  }
  if (!points.empty()) {
    const cv::Mat rows = descriptor_->compute(colour, keypoints);
    cv::Mat shares;
    const std::vector<int> classes = model_.forest.predict(rows, shares);
    const std::vector<int>& columns = model_.forest.classes();
    for (std::size_t i = 0; i < points.size(); ++i) {
      const auto column = std::find(columns.begin(), columns.end(), classes[i]) - columns.begin();
      const float share = shares.at<float>(static_cast<int>(i), static_cast<int>(column));
      points[i]->set_label({static_cast<std::uint8_t>(classes[i]), share});
    }
  }
  std::lock_guard lock(stats_mutex_);
  ++stats_.keyframes;
  stats_.points_labelled += points.size();
  stats_.points_skipped += skipped;
  stats_.keyframe_ms.push_back(watch.elapsed_ms());
}

void SemanticWorker::process_pending() {
  while (auto job = queue_.try_pop()) label(*job);
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
  for (;;) {
    queue_.wait_until([] { return false; });
    if (auto job = queue_.try_pop()) {
      label(*job);
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
