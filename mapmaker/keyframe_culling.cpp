#include "mapmaker/keyframe_culling.hpp"

#include <cmath>
#include <unordered_map>
#include <utility>

namespace facadeslam {

std::vector<std::uint64_t> redundant_keyframes(const std::map<std::uint64_t, MeasuredLevels>& keyframes,
                                               const std::set<std::uint64_t>& keep,
                                               const KeyFrameCullingOptions& options) {
  std::vector<std::uint64_t> chosen;
  if (!options.enabled) return chosen;
  // Who measures each point, at which level.
  std::unordered_map<std::uint64_t, std::vector<std::pair<std::uint64_t, int>>> observers;
  for (const auto& [keyframe, measured] : keyframes)
    for (const auto& [point, level] : measured) observers[point].emplace_back(keyframe, level);

  std::set<std::uint64_t> culled;
  for (const auto& [keyframe, measured] : keyframes) {
    if (keep.contains(keyframe) || measured.empty()) continue;
    std::size_t redundant = 0;
    for (const auto& [point, level] : measured) {
      int others = 0;
      for (const auto& [other, other_level] : observers[point])
        if (other != keyframe && !culled.contains(other) && other_level <= level + 1) ++others;
      redundant += others >= options.min_other_keyframes;
    }
    if (static_cast<double>(redundant) >= options.redundant_share * static_cast<double>(measured.size())) {
      culled.insert(keyframe);
      chosen.push_back(keyframe);
    }
  }
  return chosen;
}

}  // namespace facadeslam
