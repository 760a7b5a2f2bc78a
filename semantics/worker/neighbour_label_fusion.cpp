#include "semantics/worker/neighbour_label_fusion.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <unordered_map>
#include <utility>
#include <vector>

namespace facadeslam::semantics {
namespace {

struct LabelledPoint {
  std::shared_ptr<MapPoint> point;
  Eigen::Vector3d position;
  ClassVotes shares;    // the point's votes scaled to sum to 1
  bool finite = false;  // measured by two keyframes, nearer than kFarDepthRatio x its source's mean depth
};

bool at_finite_depth(const MapView& view, const MapPoint& point, int keyframes_measuring) {
  if (keyframes_measuring < 2) return false;
  const auto source = view.keyframe(point.source().keyframe_id);
  if (!source) return false;
  const double depth = (source->T_c_w() * point.position()).z();
  return depth > 0.0 && depth < kFarDepthRatio * source->mean_depth();
}

// The good points with votes, their positions read under the map's lock (the
// map maker moves them), ordered by id; `finite` only when `depths_needed`
// (the sky cue: it counts every keyframe's measurements).
std::vector<LabelledPoint> labelled_points(const Map& map, bool depths_needed) {
  std::vector<LabelledPoint> points;
  map.read([&](const MapView& view) {
    std::unordered_map<MapPoint::Id, int> keyframes_measuring;
    if (depths_needed)
      for (const auto& [kf_id, keyframe] : view.keyframes())
        for (const auto& [point_id, m] : keyframe->measurements()) ++keyframes_measuring[point_id];
    points.reserve(view.points().size());
    for (const auto& [id, point] : view.points()) {
      if (point->is_bad()) continue;
      ClassVotes votes = point->votes();
      float total = 0.f;
      for (const float v : votes) total += v;
      if (!(total > 0.f)) continue;
      for (float& v : votes) v /= total;
      const auto measured = keyframes_measuring.find(id);
      const int measuring = measured == keyframes_measuring.end() ? 0 : measured->second;
      points.push_back({point, point->position(), votes, at_finite_depth(view, *point, measuring)});
    }
  });
  return points;
}

// The point's label from the evidence, sky left out where the point cannot
// be sky (unless nothing else has votes).
void set_map_label(const LabelledPoint& p, ClassVotes evidence, const MapLabelOptions& options) {
  constexpr std::size_t kSky = 6;
  static_assert(kSemanticClasses[kSky].name == "sky");
  if (options.sky_only_at_infinity && p.finite) {
    float others = 0.f;
    for (std::size_t c = 0; c < evidence.size(); ++c)
      if (c != kSky) others += evidence[c];
    if (others > 0.f) evidence[kSky] = 0.f;
  }
  p.point->set_label_from(evidence);
}

// A uniform grid over the points for exact k-nearest-neighbour queries: the
// cells around the query's are searched in growing cubic shells until the
// k-th nearest distance found is within what the shells cover.
class PointGrid {
 public:
  PointGrid(const std::vector<LabelledPoint>& points, int k) : points_(points) {
    // Cell size: about k points per cell were the points spread evenly over
    // the bulk of the map (the middle 90 % on each axis: points at infinity
    // and strays would stretch the box), in as many dimensions as the bulk
    // has: a map of one wall is flat, and its box's volume says nothing of
    // how dense it is. The shell search is exact whatever the cell size;
    // the size only decides how many points it looks at.
    std::array<double, 3> extents{};
    for (int axis = 0; axis < 3; ++axis) {
      std::vector<double> values;
      values.reserve(points.size());
      for (const auto& p : points) values.push_back(p.position[axis]);
      const auto at = [&](double q) {
        auto it = values.begin() + static_cast<std::ptrdiff_t>(q * static_cast<double>(values.size() - 1));
        std::nth_element(values.begin(), it, values.end());
        return *it;
      };
      extents[static_cast<std::size_t>(axis)] = at(0.95) - at(0.05);
    }
    std::sort(extents.begin(), extents.end(), std::greater<>());
    const double per_cell = static_cast<double>(std::max(1, k)) / static_cast<double>(points.size());
    cell_ = std::max({std::cbrt(extents[0] * extents[1] * extents[2] * per_cell),
                      std::sqrt(extents[0] * extents[1] * per_cell), extents[0] * per_cell, 1e-9});
    for (std::size_t i = 0; i < points.size(); ++i) cells_[key(cell_of(points[i].position))].push_back(i);
  }

  // Indices of the k nearest points to point `query` (itself included),
  // nearest first; ties by index. At most kMaxShells shells are searched,
  // so an isolated point (far off the map) takes what lies within them.
  std::vector<std::size_t> nearest(std::size_t query, std::size_t k) const {
    const Eigen::Vector3d& q = points_[query].position;
    const Eigen::Vector3i centre = cell_of(q);
    candidates_.clear();
    for (int shell = 0; shell <= kMaxShells; ++shell) {
      visit_shell(centre, shell,
                  [&](std::size_t j) { candidates_.emplace_back((points_[j].position - q).squaredNorm(), j); });
      // Every point outside the shells searched lies at least shell * cell
      // away: done when the k-th nearest found is closer.
      if (candidates_.size() >= k) {
        std::nth_element(candidates_.begin(), candidates_.begin() + static_cast<std::ptrdiff_t>(k - 1),
                         candidates_.end());
        const double reach = static_cast<double>(shell) * cell_;
        if (candidates_[k - 1].first <= reach * reach) break;
      }
    }
    const std::size_t n = std::min(k, candidates_.size());
    std::partial_sort(candidates_.begin(), candidates_.begin() + static_cast<std::ptrdiff_t>(n), candidates_.end());
    std::vector<std::size_t> result;
    result.reserve(n);
    for (std::size_t i = 0; i < n; ++i) result.push_back(candidates_[i].second);
    return result;
  }

 private:
  Eigen::Vector3i cell_of(const Eigen::Vector3d& p) const {
    // Clamped so that a point at infinity's huge coordinates stay integers.
    const auto index = [&](double v) {
      return static_cast<int>(std::clamp(std::floor(v / cell_), -kMaxCell, kMaxCell));
    };
    return {index(p.x()), index(p.y()), index(p.z())};
  }
  // 21 bits per axis: the clamped cell index plus the shell reach, offset to
  // be non-negative, so that three of them pack into 63 bits.
  static constexpr int kMaxShells = 6;  // see nearest()
  static constexpr double kMaxCell = 1e6;
  static constexpr std::uint64_t kAxisBits = 21;
  static constexpr std::int64_t kOffset = std::int64_t{1} << (kAxisBits - 1);
  static_assert(kMaxCell + kMaxShells < static_cast<double>(kOffset),
                "the offset must cover the clamped range and the shells");
  static std::uint64_t key(const Eigen::Vector3i& c) {
    const auto axis = [](int v) { return static_cast<std::uint64_t>(static_cast<std::int64_t>(v) + kOffset); };
    return (axis(c.x()) << (2 * kAxisBits)) | (axis(c.y()) << kAxisBits) | axis(c.z());
  }
  // The cells at Chebyshev distance exactly `shell` from `centre`.
  template <class F>
  void visit_shell(const Eigen::Vector3i& centre, int shell, F&& f) const {
    for (int dx = -shell; dx <= shell; ++dx)
      for (int dy = -shell; dy <= shell; ++dy)
        for (int dz = -shell; dz <= shell; ++dz) {
          if (std::max({std::abs(dx), std::abs(dy), std::abs(dz)}) != shell) continue;
          const auto it = cells_.find(key(centre + Eigen::Vector3i(dx, dy, dz)));
          if (it == cells_.end()) continue;
          for (const std::size_t j : it->second) f(j);
        }
  }

  const std::vector<LabelledPoint>& points_;
  double cell_ = 1.0;
  std::unordered_map<std::uint64_t, std::vector<std::size_t>> cells_;
  mutable std::vector<std::pair<double, std::size_t>> candidates_;
};

}  // namespace

std::size_t fuse_labels_with_neighbours(const Map& map, const MapLabelOptions& options) {
  const std::vector<LabelledPoint> points = labelled_points(map, options.sky_only_at_infinity);
  if (points.empty()) return 0;
  if (options.neighbours <= 0) {
    for (const auto& p : points) set_map_label(p, p.shares, options);
    return points.size();
  }
  const PointGrid grid(points, options.neighbours);
  const std::size_t k = static_cast<std::size_t>(options.neighbours) + 1;  // the point itself and its neighbours
  for (std::size_t i = 0; i < points.size(); ++i) {
    ClassVotes sum{};
    for (const std::size_t j : grid.nearest(i, k))
      for (std::size_t c = 0; c < sum.size(); ++c) sum[c] += points[j].shares[c];
    set_map_label(points[i], sum, options);
  }
  return points.size();
}

}  // namespace facadeslam::semantics
