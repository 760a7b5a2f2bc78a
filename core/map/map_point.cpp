#include "core/map/map_point.hpp"

#include <bit>
#include <mutex>

namespace facadeslam {

MapPoint::MapPoint(Id id, PatchSource source, const PointGeometry& geometry)
    : id_(id),
      source_(std::move(source)),
      geometry_(geometry),
      view_(source_),
      view_geometry_(geometry),
      packed_label_(kUnlabelled),
      packed_own_label_(kUnlabelled) {}

namespace {

// Label and confidence travel in one 64-bit atomic so a reader never sees a
// label paired with another label's confidence.
SemanticLabel unpack(const std::atomic<std::uint64_t>& packed_label) {
  const std::uint64_t packed = packed_label.load(std::memory_order_acquire);
  return {static_cast<std::uint8_t>(packed & 0xff), std::bit_cast<float>(static_cast<std::uint32_t>(packed >> 8))};
}

void pack(std::atomic<std::uint64_t>& packed_label, SemanticLabel label) {
  const std::uint64_t packed =
      (static_cast<std::uint64_t>(std::bit_cast<std::uint32_t>(label.confidence)) << 8) | label.label;
  packed_label.store(packed, std::memory_order_release);
}

}  // namespace

SemanticLabel MapPoint::label() const { return unpack(packed_label_); }
SemanticLabel MapPoint::own_label() const { return unpack(packed_own_label_); }
void MapPoint::set_label_from(const ClassVotes& evidence) { pack(packed_label_, label_from_votes(evidence)); }

void MapPoint::set_labels_from_votes() {
  const SemanticLabel own = label_from_votes(votes_);
  pack(packed_own_label_, own);
  pack(packed_label_, own);
}

SemanticLabel label_from_votes(const ClassVotes& votes) {
  float total = 0.f;
  std::size_t best = 0;
  for (std::size_t c = 0; c < votes.size(); ++c) {
    total += votes[c];
    if (votes[c] > votes[best]) best = c;
  }
  if (!(total > 0.f)) return {};
  return {static_cast<std::uint8_t>(best), votes[best] / total};
}

ClassVotes MapPoint::votes() const {
  std::lock_guard lock(votes_mutex_);
  return votes_;
}

void MapPoint::add_votes(const ClassVotes& votes) {
  std::lock_guard lock(votes_mutex_);
  for (std::size_t c = 0; c < votes.size(); ++c) votes_[c] += votes[c];
  set_labels_from_votes();
}

void MapPoint::set_votes(const ClassVotes& votes) {
  std::lock_guard lock(votes_mutex_);
  votes_ = votes;
  set_labels_from_votes();
}

MapPoint::RegionViews MapPoint::region_views() const {
  std::lock_guard lock(votes_mutex_);
  return region_views_;
}

void MapPoint::add_region_view(bool in_region) {
  std::lock_guard lock(votes_mutex_);
  ++region_views_.views;
  region_views_.in_region += in_region;
  publish_region_views();
}

void MapPoint::set_region_views(const RegionViews& views) {
  std::lock_guard lock(votes_mutex_);
  region_views_ = views;
  publish_region_views();
}

void MapPoint::publish_region_views() {
  // Most of the views, not half: a tie is no region.
  in_moving_region_.store(2 * region_views_.in_region > region_views_.views, std::memory_order_release);
}

PointGeometry fronto_parallel_geometry(const Eigen::Matrix3d& R_w_c, const Eigen::Vector3d& centre_w,
                                       const Eigen::Vector3d& ray_c, const Eigen::Vector3d& ray_right_c,
                                       const Eigen::Vector3d& ray_down_c, double depth) {
  PointGeometry g;
  const Eigen::Vector3d p_c = ray_c * depth;
  g.p_w = R_w_c * p_c + centre_w;
  g.right_w = R_w_c * ((ray_right_c - ray_c) * depth);
  g.down_w = R_w_c * ((ray_down_c - ray_c) * depth);
  g.normal_w = (centre_w - g.p_w).normalized();
  return g;
}

}  // namespace facadeslam
