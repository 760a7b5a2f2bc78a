#include "semantics/evaluation/training_sample.hpp"

#include <algorithm>
#include <random>
#include <tuple>

#include "core/util/error.hpp"

namespace facadeslam::semantics {
namespace {

// The first `count` entries of a random permutation of `items` (partial
// Fisher-Yates with an explicit generator, so results do not depend on the
// standard library's shuffle).
template <typename T>
std::vector<T> pick_without_replacement(std::vector<T> items, std::size_t count, std::mt19937_64& rng) {
  count = std::min(count, items.size());
  for (std::size_t i = 0; i < count; ++i) {
    const std::size_t j = i + static_cast<std::size_t>(rng() % (items.size() - i));
    std::swap(items[i], items[j]);
  }
  items.resize(count);
  return items;
}

}  // namespace

std::size_t balanced_class_target(const std::vector<std::size_t>& class_counts, std::size_t max_samples) {
  std::vector<std::size_t> present;
  for (const std::size_t c : class_counts)
    if (c > 0) present.push_back(c);
  if (present.empty()) return 0;
  std::sort(present.begin(), present.end());
  // Upper median for an even count: keeps more data.
  std::size_t target = present[present.size() / 2];
  if (max_samples > 0) target = std::min(target, std::max<std::size_t>(1, max_samples / present.size()));
  return target;
}

std::vector<SampleCandidate> choose_training_sample(const std::vector<SampleCandidate>& candidates, int classes,
                                                    const SampleOptions& options) {
  std::mt19937_64 rng(options.seed);
  std::vector<SampleCandidate> chosen;
  if (!options.balance) {
    chosen = options.max_samples > 0 && candidates.size() > options.max_samples
                 ? pick_without_replacement(candidates, options.max_samples, rng)
                 : candidates;
  } else {
    std::vector<std::vector<SampleCandidate>> by_class(static_cast<std::size_t>(classes));
    for (const SampleCandidate& c : candidates) {
      if (c.class_id >= classes) throw Error("training sample: a keypoint's class id is outside the class table");
      by_class[c.class_id].push_back(c);
    }
    std::vector<std::size_t> counts;
    for (const auto& group : by_class) counts.push_back(group.size());
    const std::size_t target = balanced_class_target(counts, options.max_samples);
    for (const auto& group : by_class) {
      if (group.empty()) continue;
      if (group.size() >= target) {
        const auto picked = pick_without_replacement(group, target, rng);
        chosen.insert(chosen.end(), picked.begin(), picked.end());
      } else {
        chosen.insert(chosen.end(), group.begin(), group.end());
        for (std::size_t extra = group.size(); extra < target; ++extra)
          chosen.push_back(group[static_cast<std::size_t>(rng() % group.size())]);
      }
    }
  }
  std::sort(chosen.begin(), chosen.end(), [](const SampleCandidate& a, const SampleCandidate& b) {
    return std::tie(a.image, a.keypoint) < std::tie(b.image, b.keypoint);
  });
  return chosen;
}

}  // namespace facadeslam::semantics
