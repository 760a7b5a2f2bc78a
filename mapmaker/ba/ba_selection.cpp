#include "mapmaker/ba/ba_selection.hpp"

#include <algorithm>
#include <string>
#include <utility>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

[[noreturn]] void fail_selection(const std::string& what) { throw Error("bundle adjustment selection: " + what); }

// The ids as a set, checking they are unique.
std::set<std::uint64_t> keyframe_ids(const std::vector<KeyFrameCentre>& keyframes) {
  std::set<std::uint64_t> ids;
  for (const KeyFrameCentre& kf : keyframes)
    if (!ids.insert(kf.id).second) fail_selection("keyframe id " + std::to_string(kf.id) + " appears twice");
  return ids;
}

void check_observations(const std::set<std::uint64_t>& ids, const std::vector<ObservationRef>& observations) {
  for (const ObservationRef& obs : observations)
    if (!ids.contains(obs.keyframe_id))
      fail_selection("an observation of point " + std::to_string(obs.point_id) + " names keyframe id " +
                     std::to_string(obs.keyframe_id) + ", which is not among the keyframes");
}

}  // namespace

BaSelection local_ba_selection(const std::vector<KeyFrameCentre>& keyframes,
                               const std::vector<ObservationRef>& observations, std::uint64_t newest,
                               const LocalBaOptions& options) {
  const std::set<std::uint64_t> ids = keyframe_ids(keyframes);
  check_observations(ids, observations);
  for (const KeyFrameCentre& kf : keyframes)
    if (!kf.centre_w.allFinite()) fail_selection("keyframe id " + std::to_string(kf.id) + " has a non-finite centre");
  const auto newest_it =
      std::find_if(keyframes.begin(), keyframes.end(), [&](const KeyFrameCentre& kf) { return kf.id == newest; });
  if (newest_it == keyframes.end())
    fail_selection("the newest keyframe id " + std::to_string(newest) + " is not among the keyframes");
  const std::uint64_t gauge = *ids.begin();

  BaSelection selection;
  if (newest != gauge) selection.free_keyframes.insert(newest);

  // Nearest neighbours by centre distance, ties by id, gauge excluded.
  std::vector<std::pair<double, std::uint64_t>> candidates;
  for (const KeyFrameCentre& kf : keyframes)
    if (kf.id != newest && kf.id != gauge)
      candidates.emplace_back((kf.centre_w - newest_it->centre_w).squaredNorm(), kf.id);
  const std::size_t count = std::min(options.neighbours, candidates.size());
  std::partial_sort(candidates.begin(), candidates.begin() + static_cast<std::ptrdiff_t>(count), candidates.end());
  for (std::size_t i = 0; i < count; ++i) selection.free_keyframes.insert(candidates[i].second);

  for (const ObservationRef& obs : observations)
    if (selection.free_keyframes.contains(obs.keyframe_id)) selection.free_points.insert(obs.point_id);
  for (const ObservationRef& obs : observations)
    if (!selection.free_keyframes.contains(obs.keyframe_id) && selection.free_points.contains(obs.point_id))
      selection.fixed_keyframes.insert(obs.keyframe_id);
  return selection;
}

BaSelection global_ba_selection(const std::vector<KeyFrameCentre>& keyframes,
                                const std::vector<ObservationRef>& observations) {
  const std::set<std::uint64_t> ids = keyframe_ids(keyframes);
  if (ids.empty()) fail_selection("a global bundle adjustment needs at least one keyframe");
  check_observations(ids, observations);
  BaSelection selection;
  selection.fixed_keyframes.insert(*ids.begin());
  selection.free_keyframes.insert(std::next(ids.begin()), ids.end());
  for (const ObservationRef& obs : observations) selection.free_points.insert(obs.point_id);
  return selection;
}

}  // namespace facadeslam
