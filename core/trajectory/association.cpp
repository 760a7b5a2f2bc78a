#include "core/trajectory/association.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/util/error.hpp"

namespace facadeslam {
namespace {

// See the header: absorbs the rounding of decimal timestamps stored as doubles.
constexpr double kTimestampSlack = 1e-6;

struct Candidate {
  double dt = 0.0;
  std::size_t gt_index = 0;
  std::size_t est_index = 0;
};

}  // namespace

std::vector<AssociatedPair> associate_by_time(const Trajectory& gt, const Trajectory& est, double max_dt) {
  if (!std::isfinite(max_dt) || max_dt < 0.0)
    throw Error("time association: the maximum time difference must be a finite number >= 0, got " +
                std::to_string(max_dt));
  const double limit = max_dt + kTimestampSlack;

  // Every pair within the limit; both trajectories are sorted by time, so the
  // ground-truth poses near one estimate pose form a contiguous run.
  std::vector<Candidate> candidates;
  for (std::size_t e = 0; e < est.size(); ++e) {
    const double t = est[e].timestamp;
    auto first = std::lower_bound(gt.begin(), gt.end(), t - limit,
                                  [](const StampedPose& p, double value) { return p.timestamp < value; });
    for (auto it = first; it != gt.end() && it->timestamp <= t + limit; ++it)
      candidates.push_back({std::abs(it->timestamp - t), static_cast<std::size_t>(it - gt.begin()), e});
  }

  // Closest first; ties broken by index so the result never depends on the sort.
  std::sort(candidates.begin(), candidates.end(), [](const Candidate& a, const Candidate& b) {
    if (a.dt != b.dt) return a.dt < b.dt;
    if (a.est_index != b.est_index) return a.est_index < b.est_index;
    return a.gt_index < b.gt_index;
  });

  std::vector<char> gt_used(gt.size(), 0), est_used(est.size(), 0);
  std::vector<AssociatedPair> pairs;
  for (const auto& c : candidates) {
    if (gt_used[c.gt_index] || est_used[c.est_index]) continue;
    gt_used[c.gt_index] = est_used[c.est_index] = 1;
    pairs.push_back({c.gt_index, c.est_index});
  }
  std::sort(pairs.begin(), pairs.end(),
            [](const AssociatedPair& a, const AssociatedPair& b) { return a.est_index < b.est_index; });
  return pairs;
}

}  // namespace facadeslam
