#pragma once
// The map shared by the tracker, the map maker and the semantic worker.
//
// Locking (one std::shared_mutex, held briefly):
// - structure (which keyframes and points exist) and geometry (keyframe poses,
//   point positions) change only under an exclusive lock, taken by the map
//   maker for a few microseconds to publish a new keyframe, new points or
//   bundle-adjustment results that it computed without the lock;
// - readers take a shared lock just long enough to copy what they need
//   (snapshot_points(), keyframes()), then work on the copy;
// - objects are published fully built, so nobody ever sees a half-made one;
// - semantic labels and tracker statistics are atomics in MapPoint and need
//   no lock at all.
#include <atomic>
#include <cstdint>
#include <map>
#include <memory>
#include <shared_mutex>
#include <vector>

#include "core/map/keyframe.hpp"
#include "core/map/map_point.hpp"

namespace facadeslam {

// A point with a copy of its geometry, taken under the map's lock.
struct PointSnapshot {
  std::shared_ptr<MapPoint> point;
  PointGeometry geometry;
};

class Map {
 public:
  Map() = default;
  Map(const Map&) = delete;
  Map& operator=(const Map&) = delete;

  std::shared_mutex& mutex() const { return mutex_; }

  // Fresh ids, unique for the life of the map (also across save/load).
  KeyFrame::Id new_keyframe_id();
  MapPoint::Id new_point_id();

  // Publish (exclusive lock inside).
  void add_keyframe(std::shared_ptr<KeyFrame> keyframe);
  void add_point(std::shared_ptr<MapPoint> point);
  void add(const std::vector<std::shared_ptr<KeyFrame>>& keyframes,
           const std::vector<std::shared_ptr<MapPoint>>& points);

  // Copies under a shared lock, ordered by id.
  std::vector<std::shared_ptr<KeyFrame>> keyframes() const;
  std::vector<std::shared_ptr<MapPoint>> points() const;
  std::vector<PointSnapshot> snapshot_points() const;  // good points only
  std::shared_ptr<KeyFrame> keyframe(KeyFrame::Id id) const;
  std::shared_ptr<MapPoint> point(MapPoint::Id id) const;

  // Lookups for a caller that already holds the lock (shared or exclusive).
  std::shared_ptr<KeyFrame> keyframe_locked(KeyFrame::Id id) const;
  std::shared_ptr<MapPoint> point_locked(MapPoint::Id id) const;

  std::size_t keyframe_count() const;
  std::size_t point_count() const;

  // Removes points marked bad (exclusive lock) and returns their ids; the
  // caller (map maker) drops their measurements from its keyframes.
  std::vector<MapPoint::Id> remove_bad_points();

  // Empties the map (failed initialisation, reset after a long loss).
  void clear();

  // Bumped at every change of structure or geometry, so a reader can tell
  // whether its copy is stale without comparing contents.
  std::uint64_t version() const;
  // For writers that changed geometry under an exclusive lock they hold.
  void bump_version_locked() { ++version_; }

  // Id counters, for map I/O: restored on load so ids stay unique.
  std::uint64_t next_keyframe_id_value() const { return next_keyframe_id_.load(); }
  std::uint64_t next_point_id_value() const { return next_point_id_.load(); }
  void restore_next_ids(std::uint64_t keyframe, std::uint64_t point);

 private:
  mutable std::shared_mutex mutex_;
  std::map<KeyFrame::Id, std::shared_ptr<KeyFrame>> keyframes_;
  std::map<MapPoint::Id, std::shared_ptr<MapPoint>> points_;
  std::atomic<std::uint64_t> next_keyframe_id_{0};
  std::atomic<std::uint64_t> next_point_id_{0};
  std::uint64_t version_ = 0;
};

}  // namespace facadeslam
