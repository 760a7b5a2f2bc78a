#pragma once
// A map point: a 3D position in the world frame plus the 8x8 image patch it
// was created from (PTAM). The patch is not copied: it is re-read from the
// source keyframe's pyramid level and warped into each new view by the affine
// map that the point's local surface induces. For that the point keeps, in the
// world frame, the offsets that one source-level pixel to the right and one
// down correspond to at the point's depth (PTAM's v3PixelRight_W /
// v3PixelDown_W, on a plane facing the source camera); they are refreshed
// whenever bundle adjustment moves the point or its source keyframe.
//
// Threads: the geometry and the bad flag belong to the Map: they change only
// through Map::update (the map maker's bundle adjustment and outlier removal)
// and other threads read the geometry from Map::snapshot_points or under
// Map::read. The semantic label and the search counts are atomics: the
// semantic worker and the tracker write them without blocking anyone.
#include <array>
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>

#include <Eigen/Core>

#include "core/image/image_pyramid.hpp"
#include "core/map/semantic_classes.hpp"

namespace facadeslam {

// Class ids of the semantic labels; 255 = not labelled yet.
inline constexpr std::uint8_t kUnlabelled = 255;

struct SemanticLabel {
  std::uint8_t label = kUnlabelled;
  float confidence = 0.f;
  bool operator==(const SemanticLabel&) const = default;
};

// Per-class vote sums of a point's observations, indexed by class id: each
// labelled observation adds the forest's vote shares (which sum to 1), so the
// label is the arg-max and the confidence the winner's share of all votes.
using ClassVotes = std::array<float, kSemanticClasses.size()>;

// The label that votes give: arg-max (the lowest id on a tie) and its share;
// kUnlabelled when there are no votes.
SemanticLabel label_from_votes(const ClassVotes& votes);

// Where a point's patch comes from: the keyframe that made it, until the
// map maker culls that keyframe and hands the point to another one that
// measures it (MapEditor::set_source).
struct PatchSource {
  std::uint64_t keyframe_id = 0;
  std::shared_ptr<const ImagePyramid> pyramid;  // the source keyframe's images
  int level = 0;                                // pyramid level of the patch
  Eigen::Vector2d pixel_level0{0, 0};           // patch centre, level-0 pixels
};

struct PointGeometry {
  Eigen::Vector3d p_w{0, 0, 0};       // position
  Eigen::Vector3d right_w{0, 0, 0};   // world offset of one source-level pixel to the right
  Eigen::Vector3d down_w{0, 0, 0};    // ... and one pixel down
  Eigen::Vector3d normal_w{0, 0, 1};  // unit vector from the point towards its source camera
};

class MapPoint {
 public:
  using Id = std::uint64_t;

  MapPoint(Id id, PatchSource source, const PointGeometry& geometry);

  Id id() const { return id_; }

  // Owned by the Map (see above). The source changes only when its keyframe
  // is culled; threads other than the map maker read it from
  // Map::snapshot_points or under Map::read.
  const PatchSource& source() const { return source_; }
  const PointGeometry& geometry() const { return geometry_; }
  const Eigen::Vector3d& position() const { return geometry_.p_w; }
  // The patch the tracker searches for and its geometry: the point as the
  // newest keyframe that measured it saw it (its source until another
  // keyframe does). Under forward motion the source's view soon differs so
  // much (scale, obliquity) that its patch no longer matches; a recent view
  // does (as SVO takes the nearest keyframe's patch). Bundle adjustment and
  // the map file keep using the source.
  const PatchSource& view() const { return view_; }
  const PointGeometry& view_geometry() const { return view_geometry_; }

  // Two labels, lock-free; written by the semantic worker. label() is the
  // map's: the point's votes fused with its map neighbours'
  // (semantics/worker/neighbour_label_fusion; until the worker fuses, its
  // own), what the outputs show. own_label() is what the point's own views
  // say, what the tracker weighs points by: fused labels call more of a
  // still tree vegetation, and the demo's threaded ATE went 0.46-0.48 ->
  // 0.49-0.50 % with them (docs/benchmarks.md).
  SemanticLabel label() const;
  SemanticLabel own_label() const;
  // The vote sums behind the labels. add_votes fuses one more observation's
  // votes and sets both labels from them; set_votes replaces them (loading a
  // map). Only the semantic worker writes votes while the system runs.
  ClassVotes votes() const;
  void add_votes(const ClassVotes& votes);
  void set_votes(const ClassVotes& votes);
  // The map's label from `evidence` (the votes fused with the neighbours');
  // the votes and the own label stay the point's.
  void set_label_from(const ClassVotes& evidence);

  // Region-level evidence (the semantic worker's moving-region detector,
  // semantics/worker/moving_regions.hpp): of the views the detector looked
  // at, how many saw the point inside a region dense with calls of a moving
  // class. A point most of whose views did is in a moving region, whatever
  // its own label: one by one the forest calls a close-up car's points
  // building or road, yet their region is full of car calls. Written by the
  // semantic worker (add_region_view) or when loading a map
  // (set_region_views).
  struct RegionViews {
    std::uint32_t views = 0;
    std::uint32_t in_region = 0;  // <= views
    bool operator==(const RegionViews&) const = default;
  };
  RegionViews region_views() const;
  void add_region_view(bool in_region);
  void set_region_views(const RegionViews& views);
  bool in_moving_region() const { return in_moving_region_.load(std::memory_order_acquire); }

  // Marked bad by the map maker (MapEditor::mark_bad); snapshots leave bad
  // points out and Map::remove_bad_points removes them.
  bool is_bad() const { return bad_.load(std::memory_order_acquire); }

  // Tracker statistics for outlier removal (PTAM: a point searched for often
  // and rarely found is discarded). Relaxed atomics: counts, not ordering.
  void count_search(bool found) {
    searched_.fetch_add(1, std::memory_order_relaxed);
    if (found) found_.fetch_add(1, std::memory_order_relaxed);
  }
  std::uint32_t times_searched() const { return searched_.load(std::memory_order_relaxed); }
  std::uint32_t times_found() const { return found_.load(std::memory_order_relaxed); }

 private:
  friend class MapEditor;

  const Id id_;
  PatchSource source_;
  PointGeometry geometry_;
  PatchSource view_;
  PointGeometry view_geometry_;
  void set_labels_from_votes();  // under votes_mutex_
  void publish_region_views();   // under votes_mutex_: in_moving_region_ from region_views_

  // Label in the low byte, confidence bits above.
  std::atomic<std::uint64_t> packed_label_, packed_own_label_;
  // The votes are read rarely (outputs, the map file) and written by one
  // thread; a mutex keeps a reader from seeing half an update.
  mutable std::mutex votes_mutex_;
  ClassVotes votes_{};
  RegionViews region_views_;  // under votes_mutex_
  std::atomic<bool> in_moving_region_{false};
  std::atomic<bool> bad_{false};
  std::atomic<std::uint32_t> searched_{0}, found_{0};
};

// Builds the geometry of a point seen at `pixel_level0` at `level` of a camera
// with pose T_c_w (given as rotation R_w_c and centre), at depth `depth` along
// the ray `ray_c` (z = 1 plane), for a patch facing the camera: the pixel
// offsets are the ray offsets of one level-pixel scaled by the depth.
PointGeometry fronto_parallel_geometry(const Eigen::Matrix3d& R_w_c, const Eigen::Vector3d& centre_w,
                                       const Eigen::Vector3d& ray_c, const Eigen::Vector3d& ray_right_c,
                                       const Eigen::Vector3d& ray_down_c, double depth);

}  // namespace facadeslam
