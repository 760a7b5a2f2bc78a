#include "mapmaker/new_point_candidates.hpp"

#include <algorithm>

namespace facadeslam {

NewPointCandidates::NewPointCandidates(const KeyFrame& keyframe, int level, double min_distance)
    : corners_(keyframe.pyramid()->level(level).corners), min_distance2_(min_distance * min_distance) {
  std::sort(corners_.begin(), corners_.end(), [](const Corner& a, const Corner& b) { return a.score > b.score; });
  for (const auto& [id, m] : keyframe.measurements())
    if (m.level == level || m.level == level + 1) taken_.push_back(ImagePyramid::level0_to_level(m.pixel, level));
}

bool NewPointCandidates::near_taken(const Eigen::Vector2d& level_pixel) const {
  return std::any_of(taken_.begin(), taken_.end(),
                     [&](const Eigen::Vector2d& t) { return (t - level_pixel).squaredNorm() < min_distance2_; });
}

}  // namespace facadeslam
