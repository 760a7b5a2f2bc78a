#include "core/map/map.hpp"

namespace facadeslam {

void NewPoints::append(NewPoints more) {
  points.insert(points.end(), std::make_move_iterator(more.points.begin()), std::make_move_iterator(more.points.end()));
  observations.insert(observations.end(), std::make_move_iterator(more.observations.begin()),
                      std::make_move_iterator(more.observations.end()));
}

const KeyFrame* nearest_keyframe(const std::map<KeyFrame::Id, std::shared_ptr<KeyFrame>>& keyframes,
                                 const Eigen::Vector3d& centre_w) {
  const KeyFrame* nearest = nullptr;
  double nearest_distance = 0.0;
  for (const auto& [id, kf] : keyframes)
    if (const double d = (kf->centre_w() - centre_w).squaredNorm(); !nearest || d < nearest_distance) {
      nearest = kf.get();
      nearest_distance = d;
    }
  return nearest;
}

std::shared_ptr<KeyFrame> MapView::keyframe(KeyFrame::Id id) const {
  const auto it = map_.keyframes_.find(id);
  return it == map_.keyframes_.end() ? nullptr : it->second;
}

std::shared_ptr<MapPoint> MapView::point(MapPoint::Id id) const {
  const auto it = map_.points_.find(id);
  return it == map_.points_.end() ? nullptr : it->second;
}

const std::map<KeyFrame::Id, std::shared_ptr<KeyFrame>>& MapView::keyframes() const { return map_.keyframes_; }
const std::map<MapPoint::Id, std::shared_ptr<MapPoint>>& MapView::points() const { return map_.points_; }

void MapEditor::set_depth_stats(KeyFrame& keyframe, double mean, double sigma) {
  keyframe.mean_depth_ = mean;
  keyframe.depth_sigma_ = sigma;
}

void MapEditor::set_geometry(MapPoint& point, const PointGeometry& geometry) {
  point.geometry_ = geometry;
  if (point.view_.keyframe_id == point.source_.keyframe_id) point.view_geometry_ = geometry;
}

void MapEditor::set_view(MapPoint& point, const PatchSource& view, const PointGeometry& geometry) {
  point.view_ = view;
  point.view_geometry_ = geometry;
}

void MapEditor::set_source(MapPoint& point, KeyFrame& keyframe, const PatchSource& source,
                           const PointGeometry& geometry) {
  point.source_ = source;
  point.geometry_ = geometry;
  if (const auto it = keyframe.measurements_.find(point.id()); it != keyframe.measurements_.end())
    it->second.from_source = true;
}

void MapEditor::cull_keyframe(KeyFrame::Id id, const CulledKeyFrame& link) {
  editable_.keyframes_.erase(id);
  editable_.culled_[id] = link;
}

bool MapEditor::erase_measurement(KeyFrame& keyframe, MapPoint::Id point) {
  return keyframe.measurements_.erase(point) > 0;
}

KeyFrame::Id Map::new_keyframe_id() { return next_keyframe_id_.fetch_add(1); }
MapPoint::Id Map::new_point_id() { return next_point_id_.fetch_add(1); }

void Map::restore_next_ids(std::uint64_t keyframe, std::uint64_t point) {
  next_keyframe_id_ = keyframe;
  next_point_id_ = point;
}

void Map::add(const std::vector<std::shared_ptr<KeyFrame>>& keyframes,
              const std::vector<std::shared_ptr<MapPoint>>& points, const std::vector<Observation>& observations) {
  std::unique_lock lock(mutex_);
  ++revision_;
  for (const auto& kf : keyframes) keyframes_.emplace(kf->id(), kf);
  for (const auto& p : points) points_.emplace(p->id(), p);
  for (const auto& o : observations) o.keyframe->measurements_[o.point] = o.measurement;
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

std::vector<KeyFrameSnapshot> Map::snapshot_keyframes() const {
  std::shared_lock lock(mutex_);
  std::vector<KeyFrameSnapshot> out;
  out.reserve(keyframes_.size());
  for (const auto& [id, kf] : keyframes_) out.push_back({kf, kf->T_c_w(), kf->mean_depth(), kf->depth_sigma()});
  return out;
}

void Map::copy_good_points(std::vector<PointSnapshot>& out) const {
  out.clear();
  out.reserve(points_.size());
  for (const auto& [id, p] : points_)
    if (!p->is_bad()) out.push_back({p, p->source(), p->geometry(), p->view(), p->view_geometry()});
}

std::vector<PointSnapshot> Map::snapshot_points() const {
  std::shared_lock lock(mutex_);
  std::vector<PointSnapshot> out;
  copy_good_points(out);
  return out;
}

bool Map::refresh_points_snapshot(std::vector<PointSnapshot>& points, std::uint64_t& revision) const {
  std::shared_lock lock(mutex_);
  if (revision == revision_) return false;
  copy_good_points(points);
  revision = revision_;
  return true;
}

std::shared_ptr<KeyFrame> Map::keyframe(KeyFrame::Id id) const {
  return read([&](const MapView& map) { return map.keyframe(id); });
}

std::shared_ptr<MapPoint> Map::point(MapPoint::Id id) const {
  return read([&](const MapView& map) { return map.point(id); });
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
  ++revision_;
  std::vector<MapPoint::Id> removed;
  for (auto it = points_.begin(); it != points_.end();) {
    if (it->second->is_bad()) {
      removed.push_back(it->first);
      it = points_.erase(it);
    } else {
      ++it;
    }
  }
  if (!removed.empty())
    for (auto& [id, kf] : keyframes_)
      for (const MapPoint::Id point : removed) kf->measurements_.erase(point);
  return removed;
}

std::map<KeyFrame::Id, CulledKeyFrame> Map::culled_keyframes() const {
  std::shared_lock lock(mutex_);
  return culled_;
}

void Map::clear() {
  std::unique_lock lock(mutex_);
  ++revision_;
  keyframes_.clear();
  points_.clear();
  culled_.clear();
}

}  // namespace facadeslam
