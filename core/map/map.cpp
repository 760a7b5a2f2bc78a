#include "core/map/map.hpp"

#include <mutex>

namespace facadeslam {

KeyFrame::Id Map::new_keyframe_id() { return next_keyframe_id_.fetch_add(1); }
MapPoint::Id Map::new_point_id() { return next_point_id_.fetch_add(1); }

void Map::restore_next_ids(std::uint64_t keyframe, std::uint64_t point) {
  next_keyframe_id_ = keyframe;
  next_point_id_ = point;
}

void Map::add_keyframe(std::shared_ptr<KeyFrame> keyframe) { add({std::move(keyframe)}, {}); }

void Map::add_point(std::shared_ptr<MapPoint> point) { add({}, {std::move(point)}); }

void Map::add(const std::vector<std::shared_ptr<KeyFrame>>& keyframes,
              const std::vector<std::shared_ptr<MapPoint>>& points) {
  std::unique_lock lock(mutex_);
  for (const auto& kf : keyframes) keyframes_.emplace(kf->id(), kf);
  for (const auto& p : points) points_.emplace(p->id(), p);
  ++version_;
}

std::vector<std::shared_ptr<KeyFrame>> Map::keyframes() const {
  std::shared_lock lock(mutex_);
  std::vector<std::shared_ptr<KeyFrame>> out;
  out.reserve(keyframes_.size());
  for (const auto& [id, kf] : keyframes_) out.push_back(kf);
  return out;
}

std::vector<std::shared_ptr<MapPoint>> Map::points() const {
  std::shared_lock lock(mutex_);
  std::vector<std::shared_ptr<MapPoint>> out;
  out.reserve(points_.size());
  for (const auto& [id, p] : points_) out.push_back(p);
  return out;
}

std::vector<PointSnapshot> Map::snapshot_points() const {
  std::shared_lock lock(mutex_);
  std::vector<PointSnapshot> out;
  out.reserve(points_.size());
  for (const auto& [id, p] : points_)
    if (!p->is_bad()) out.push_back({p, p->geometry()});
  return out;
}

std::shared_ptr<KeyFrame> Map::keyframe(KeyFrame::Id id) const {
  std::shared_lock lock(mutex_);
  return keyframe_locked(id);
}

std::shared_ptr<MapPoint> Map::point(MapPoint::Id id) const {
  std::shared_lock lock(mutex_);
  return point_locked(id);
}

std::shared_ptr<KeyFrame> Map::keyframe_locked(KeyFrame::Id id) const {
  const auto it = keyframes_.find(id);
  return it == keyframes_.end() ? nullptr : it->second;
}

std::shared_ptr<MapPoint> Map::point_locked(MapPoint::Id id) const {
  const auto it = points_.find(id);
  return it == points_.end() ? nullptr : it->second;
}

std::size_t Map::keyframe_count() const {
  std::shared_lock lock(mutex_);
  return keyframes_.size();
}

std::size_t Map::point_count() const {
  std::shared_lock lock(mutex_);
  return points_.size();
}

std::vector<MapPoint::Id> Map::remove_bad_points() {
  std::unique_lock lock(mutex_);
  std::vector<MapPoint::Id> removed;
  for (auto it = points_.begin(); it != points_.end();) {
    if (it->second->is_bad()) {
      removed.push_back(it->first);
      it = points_.erase(it);
    } else {
      ++it;
    }
  }
  if (!removed.empty()) ++version_;
  return removed;
}

void Map::clear() {
  std::unique_lock lock(mutex_);
  keyframes_.clear();
  points_.clear();
  ++version_;
}

std::uint64_t Map::version() const {
  std::shared_lock lock(mutex_);
  return version_;
}

}  // namespace facadeslam
