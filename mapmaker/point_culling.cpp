#include "mapmaker/point_culling.hpp"

#include <algorithm>
#include <unordered_map>

namespace facadeslam {
namespace {

struct MeasuringKeyframes {
  int keyframes = 0;
  KeyFrame::Id newest = 0;  // the newest keyframe measuring the point
};

}  // namespace

std::vector<std::shared_ptr<MapPoint>> points_to_cull(const std::vector<std::shared_ptr<KeyFrame>>& keyframes,
                                                      const std::vector<std::shared_ptr<MapPoint>>& points,
                                                      const PointCullingOptions& options, const IsLeftOut& left_out) {
  // Measurement counts over all keyframes (the map maker, their only writer,
  // reads them without a lock).
  std::unordered_map<MapPoint::Id, MeasuringKeyframes> measured;
  KeyFrame::Id newest = 0;
  for (const auto& kf : keyframes) {
    newest = std::max(newest, kf->id());
    for (const auto& [id, m] : kf->measurements()) {
      MeasuringKeyframes& v = measured[id];
      ++v.keyframes;
      v.newest = std::max(v.newest, kf->id());
    }
  }
  const auto among_newest = [&](KeyFrame::Id id) { return id + options.grace_keyframes > newest; };
  std::vector<std::shared_ptr<MapPoint>> cull;
  for (const auto& p : points) {
    const bool rarely_found = p->times_searched() >= static_cast<std::uint32_t>(options.min_searches) &&
                              p->times_found() < options.max_found_ratio * p->times_searched();
    const auto it = measured.find(p->id());
    const bool too_few_views =
        it == measured.end() || (it->second.keyframes < 2 && !among_newest(p->source().keyframe_id));
    const bool left_out_unmeasured =
        left_out && it != measured.end() && !among_newest(it->second.newest) && left_out(*p);
    if (rarely_found || too_few_views || left_out_unmeasured) cull.push_back(p);
  }
  return cull;
}

}  // namespace facadeslam
