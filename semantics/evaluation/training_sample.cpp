#include "semantics/evaluation/training_sample.hpp"

#include <algorithm>
#include <cmath>
#include <string>
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

std::vector<std::size_t> balanced_class_rows(const std::vector<std::size_t>& class_counts, std::size_t max_samples,
                                             double balance_power) {
  if (!(balance_power > 0.0 && balance_power <= 1.0))
    throw Error("training sample: the balance power must lie in (0, 1], got " + std::to_string(balance_power));
  std::vector<std::size_t> rows(class_counts.size(), 0);
  const std::size_t median = balanced_class_target(class_counts, 0);
  if (median == 0) return rows;
  std::vector<double> wanted(class_counts.size(), 0.0);
  double total = 0.0;
  for (std::size_t c = 0; c < class_counts.size(); ++c) {
    if (class_counts[c] == 0) continue;
    const double ratio = static_cast<double>(class_counts[c]) / static_cast<double>(median);
    wanted[c] = balance_power == 1.0 ? static_cast<double>(median)
                                     : static_cast<double>(median) * std::pow(ratio, 1.0 - balance_power);
    total += wanted[c];
  }
  const double scale =
      max_samples > 0 && total > static_cast<double>(max_samples) ? static_cast<double>(max_samples) / total : 1.0;
  for (std::size_t c = 0; c < class_counts.size(); ++c)
    if (class_counts[c] > 0) rows[c] = std::max<std::size_t>(1, static_cast<std::size_t>(wanted[c] * scale));
  return rows;
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
    // Fully balanced: the (capped) median for every class, as it always was.
    std::vector<std::size_t> targets(counts.size(), balanced_class_target(counts, options.max_samples));
    if (options.balance_power != 1.0) targets = balanced_class_rows(counts, options.max_samples, options.balance_power);
    for (std::size_t c = 0; c < by_class.size(); ++c) {
      const auto& group = by_class[c];
      const std::size_t target = targets[c];
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
