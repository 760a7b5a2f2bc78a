#pragma once
// The map shared by the tracker, the map maker and the semantic worker. The
// Map owns its locking (one std::shared_mutex, never held for long, never
// visible outside):
// - readers copy what they need under the shared lock and work on the copy:
//   snapshot_points(), snapshot_keyframes(), keyframes(), points(); or visit
//   the map under the shared lock with read(), for a consistent view of many
//   objects (saving the map);
// - what changes after publication (keyframe poses, depth statistics and
//   measurements; point geometry and the bad flag) changes only through
//   update(), under the exclusive lock, and only through its MapEditor: the
//   setters are private to it. update() and add() need a non-const Map, which
//   only the map maker holds once the threads run (the tracker and the
//   semantic worker get a const Map&). The map maker may read what it alone
//   writes without a lock;
// - objects are published fully built (add()), so nobody sees a half-made one;
// - semantic labels and the tracker's search counts are atomics in MapPoint
//   and need no lock at all.
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <shared_mutex>
#include <vector>

#include "core/map/keyframe.hpp"
#include "core/map/map_point.hpp"

namespace facadeslam {

// A point with a copy of its geometry, taken under the map's lock.
struct PointSnapshot {
  std::shared_ptr<MapPoint> point;
  PatchSource source;  // MapPoint::source()
  PointGeometry geometry;
  PatchSource view;  // MapPoint::view()
  PointGeometry view_geometry;
};

// A keyframe with a copy of what the map maker may change, taken under the
// map's lock.
struct KeyFrameSnapshot {
  std::shared_ptr<const KeyFrame> keyframe;
  SE3d T_c_w;
  double mean_depth = 1.0;
  double depth_sigma = 0.0;
  Eigen::Vector3d centre_w() const { return T_c_w.inverse().translation(); }
  Eigen::Vector3d optical_axis_w() const { return facadeslam::optical_axis_w(T_c_w); }
};

// A keyframe the map maker culled as redundant, and where the frames that
// were tracked against it find their pose from then on: the surviving
// keyframe `parent` and the culled keyframe's pose relative to it when it
// went (RelativeTrajectory follows these links, as ORB-SLAM keeps a culled
// keyframe's parent and relative pose for its trajectory).
struct CulledKeyFrame {
  KeyFrame::Id parent = 0;
  SE3d T_culled_parent;
};

// A measurement to record in a keyframe that may already be in the map.
struct Observation {
  std::shared_ptr<KeyFrame> keyframe;
  MapPoint::Id point = 0;
  Measurement measurement;
};

// New points and the measurements that made them, published together.
struct NewPoints {
  std::vector<std::shared_ptr<MapPoint>> points;
  std::vector<Observation> observations;
  void append(NewPoints more);
};

// The keyframe whose centre is nearest `centre_w` (the lowest id on a tie),
// or null when there is none. Their poses must hold still meanwhile: call it
// under the map's lock (on MapView::keyframes) or from the map maker.
const KeyFrame* nearest_keyframe(const std::map<KeyFrame::Id, std::shared_ptr<KeyFrame>>& keyframes,
                                 const Eigen::Vector3d& centre_w);

class Map;

// The map as seen under its shared lock (Map::read); valid only inside the visit.
class MapView {
 public:
  std::shared_ptr<KeyFrame> keyframe(KeyFrame::Id id) const;
  std::shared_ptr<MapPoint> point(MapPoint::Id id) const;
  const std::map<KeyFrame::Id, std::shared_ptr<KeyFrame>>& keyframes() const;
  const std::map<MapPoint::Id, std::shared_ptr<MapPoint>>& points() const;

 protected:
  friend class Map;
  explicit MapView(const Map& map) : map_(map) {}
  const Map& map_;
};

// The map under its exclusive lock (Map::update): the only way to change
// what is already published.
class MapEditor : public MapView {
 public:
  void set_pose(KeyFrame& keyframe, const SE3d& T_c_w) { keyframe.T_c_w_ = T_c_w; }
  void set_depth_stats(KeyFrame& keyframe, double mean, double sigma);
  // Returns whether there was one.
  bool erase_measurement(KeyFrame& keyframe, MapPoint::Id point);
  // Moves the point; a view still at its source keyframe moves with it.
  void set_geometry(MapPoint& point, const PointGeometry& geometry);
  void set_view(MapPoint& point, const PatchSource& view, const PointGeometry& geometry);
  void mark_bad(MapPoint& point) { point.bad_.store(true, std::memory_order_release); }
  // Hands the point to another keyframe that measures it (its source
  // keyframe is being culled); that measurement becomes its source one.
  void set_source(MapPoint& point, KeyFrame& keyframe, const PatchSource& source, const PointGeometry& geometry);
  // Takes a keyframe out of the map (its measurements go with it) and
  // records where its frames find their pose. The points it was the source
  // or the view of must have been handed on first (set_source, set_view).
  void cull_keyframe(KeyFrame::Id id, const CulledKeyFrame& link);

 private:
  friend class Map;
  explicit MapEditor(Map& map) : MapView(map), editable_(map) {}
  Map& editable_;
};

class Map {
 public:
  Map() = default;
  Map(const Map&) = delete;
  Map& operator=(const Map&) = delete;

  // Fresh ids, unique for the life of the map (also across save/load).
  KeyFrame::Id new_keyframe_id();
  MapPoint::Id new_point_id();

  // Publishes new keyframes and points, and records the observations
  // (which may be in keyframes already in the map), in one exclusive section.
  void add(const std::vector<std::shared_ptr<KeyFrame>>& keyframes,
           const std::vector<std::shared_ptr<MapPoint>>& points, const std::vector<Observation>& observations = {});
  void add(const NewPoints& points) { add({}, points.points, points.observations); }
  void add_keyframe(std::shared_ptr<KeyFrame> keyframe) { add({std::move(keyframe)}, {}); }

  // Visits the map under the shared lock: f(const MapView&). `f` must not
  // call the Map itself (its functions lock too: a deadlock); use the view.
  template <class F>
  decltype(auto) read(F&& f) const {
    std::shared_lock lock(mutex_);
    return f(MapView(*this));
  }
  // Changes it under the exclusive lock: f(MapEditor&); the same rule.
  template <class F>
  decltype(auto) update(F&& f) {
    std::unique_lock lock(mutex_);
    ++revision_;
    MapEditor editor(*this);
    return f(editor);
  }

  // Copies under a shared lock, ordered by id.
  std::vector<std::shared_ptr<KeyFrame>> keyframes() const;
  std::vector<std::shared_ptr<MapPoint>> points() const;
  std::vector<KeyFrameSnapshot> snapshot_keyframes() const;
  std::vector<PointSnapshot> snapshot_points() const;  // good points only
  // Refills `points` with snapshot_points() unless the map is unchanged since
  // the call that set `revision` (start it at 0); returns whether it did.
  // Every change (add, update, remove_bad_points, clear) counts. The tracker
  // keeps its snapshot between keyframes this way instead of copying the
  // whole map every frame.
  bool refresh_points_snapshot(std::vector<PointSnapshot>& points, std::uint64_t& revision) const;
  std::shared_ptr<KeyFrame> keyframe(KeyFrame::Id id) const;
  std::shared_ptr<MapPoint> point(MapPoint::Id id) const;

  std::size_t keyframe_count() const;
  std::size_t point_count() const;

  // The keyframes culled so far (Map::clear forgets them), by id.
  std::map<KeyFrame::Id, CulledKeyFrame> culled_keyframes() const;

  // Removes the points marked bad and their measurements in every keyframe,
  // in one exclusive section; returns their ids.
  std::vector<MapPoint::Id> remove_bad_points();

  // Empties the map (failed initialisation, reset after a long loss).
  void clear();

  // Id counters, for map I/O: restored on load so ids stay unique.
  std::uint64_t next_keyframe_id_value() const { return next_keyframe_id_.load(); }
  std::uint64_t next_point_id_value() const { return next_point_id_.load(); }
  void restore_next_ids(std::uint64_t keyframe, std::uint64_t point);

 private:
  friend class MapView;
  friend class MapEditor;

  // The good points' snapshots into `out` (emptied first); mutex_ held by the caller.
  void copy_good_points(std::vector<PointSnapshot>& out) const;

  mutable std::shared_mutex mutex_;
  std::map<KeyFrame::Id, std::shared_ptr<KeyFrame>> keyframes_;
  std::map<MapPoint::Id, std::shared_ptr<MapPoint>> points_;
  std::map<KeyFrame::Id, CulledKeyFrame> culled_;
  std::uint64_t revision_ = 1;  // under mutex_: changes with every exclusive section
  std::atomic<std::uint64_t> next_keyframe_id_{0};
  std::atomic<std::uint64_t> next_point_id_{0};
};

}  // namespace facadeslam
