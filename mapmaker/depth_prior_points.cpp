#include "mapmaker/depth_prior_points.hpp"

#include <algorithm>

#include "mapmaker/new_point_candidates.hpp"
#include "mapmaker/point_geometry.hpp"

namespace facadeslam {
namespace {

struct MeasuredDepth {
  Eigen::Vector2d pixel;  // level 0
  double depth;
};

// Median depth of the `k` measured points nearest to `pixel` in the image.
double prior_depth(std::vector<MeasuredDepth>& measured, const Eigen::Vector2d& pixel, int k) {
  const auto n = static_cast<std::ptrdiff_t>(std::min<std::size_t>(measured.size(), static_cast<std::size_t>(k)));
  std::partial_sort(measured.begin(), measured.begin() + n, measured.end(), [&](const auto& a, const auto& b) {
    return (a.pixel - pixel).squaredNorm() < (b.pixel - pixel).squaredNorm();
  });
  std::vector<double> depths;
  for (std::ptrdiff_t i = 0; i < n; ++i) depths.push_back(measured[static_cast<std::size_t>(i)].depth);
  std::nth_element(depths.begin(), depths.begin() + n / 2, depths.end());
  return depths[static_cast<std::size_t>(n / 2)];
}

}  // namespace

NewPoints depth_prior_points(Map& map, const Camera& camera, const std::shared_ptr<KeyFrame>& keyframe_ptr,
                             const DepthPriorOptions& options) {
  const KeyFrame& keyframe = *keyframe_ptr;
  const SE3d T_c_w = keyframe.T_c_w();
  std::vector<MeasuredDepth> measured;
  map.read([&](const MapView& view) {
    for (const auto& [id, m] : keyframe.measurements()) {
      const auto p = view.point(id);
      if (!p || p->is_bad()) continue;
      const double z = (T_c_w * p->position()).z();
      if (z > 0) measured.push_back({m.pixel, z});
    }
  });
  if (measured.empty()) return {};

  NewPoints created;
  for (int level = 0; level < kPyramidLevels; ++level) {
    const int wanted = options.max_points_per_level[static_cast<std::size_t>(level)];
    if (wanted <= 0) continue;
    NewPointCandidates candidates(keyframe, level, options.min_distance_to_measurement);
    int made = 0;
    for (const Corner& c : candidates.corners()) {
      if (made >= wanted) break;
      const Eigen::Vector2d at(c.x, c.y);
      if (candidates.near_taken(at)) continue;
      const Eigen::Vector2d pixel0 = ImagePyramid::level_to_level0(at, level);
      const double depth = prior_depth(measured, pixel0, options.depth_neighbours);
      // unproject() gives the ray on the z = 1 plane, so `depth` scales it to z = depth.
      const Eigen::Vector3d p_w = T_c_w.inverse() * (camera.unproject(pixel0) * depth);
      const PatchSource source{keyframe.id(), keyframe.pyramid(), level, pixel0};
      auto point = std::make_shared<MapPoint>(map.new_point_id(), source, source_geometry(camera, T_c_w, source, p_w));
      // Recorded when published; the next level's candidates do not look at this level.
      created.observations.push_back({keyframe_ptr, point->id(), {level, pixel0, true}});
      candidates.take(at);
      created.points.push_back(std::move(point));
      ++made;
    }
  }
  return created;
}

}  // namespace facadeslam
