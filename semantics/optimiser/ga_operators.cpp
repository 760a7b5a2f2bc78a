#include "semantics/optimiser/ga_operators.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

namespace facadeslam::semantics {

std::vector<double> scale_linearly(const std::vector<double>& objectives, double multiple) {
  std::vector<double> fitness(objectives.size(), 0.0);
  double lowest = std::numeric_limits<double>::infinity();
  for (const double o : objectives)
    if (std::isfinite(o)) lowest = std::min(lowest, o);
  if (!std::isfinite(lowest)) return fitness;  // nothing valid: all equal
  double sum = 0.0, best = 0.0;
  std::size_t valid = 0;
  for (std::size_t i = 0; i < objectives.size(); ++i) {
    if (!std::isfinite(objectives[i])) continue;
    fitness[i] = objectives[i] - lowest;
    sum += fitness[i];
    best = std::max(best, fitness[i]);
    ++valid;
  }
  const double mean = sum / static_cast<double>(valid);
  if (best - mean <= 1e-12 * std::max(1.0, best)) {
    // All valid genomes alike: equal chances.
    for (std::size_t i = 0; i < objectives.size(); ++i) fitness[i] = std::isfinite(objectives[i]) ? 1.0 : 0.0;
    return fitness;
  }
  // After the shift the worst valid fitness is 0. Mapping the best to
  // multiple x mean with the mean kept gives f' = a f + b with
  // b = mean (best - multiple mean) / (best - mean), which keeps the worst at
  // or above 0 only when best > multiple x mean. Otherwise the worst stays
  // at 0 and the mean is kept: the shifted fitness as it is (its best is
  // then at most multiple x the mean already).
  double a = 1.0, b = 0.0;
  if (best > multiple * mean) {
    a = (multiple - 1.0) * mean / (best - mean);
    b = mean * (best - multiple * mean) / (best - mean);
  }
  for (std::size_t i = 0; i < objectives.size(); ++i)
    if (std::isfinite(objectives[i])) fitness[i] = std::max(0.0, a * fitness[i] + b);
  return fitness;
}

namespace {

// Index whose cumulative fitness first exceeds `r` (r in [0, total)).
std::size_t spin(const std::vector<double>& cumulative, double r) {
  const auto it = std::upper_bound(cumulative.begin(), cumulative.end(), r);
  return std::min(static_cast<std::size_t>(it - cumulative.begin()), cumulative.size() - 1);
}

}  // namespace

std::vector<std::size_t> select_parents(const std::vector<double>& fitness, std::size_t count, const GaOptions& options,
                                        GaRandom& rng) {
  const std::size_t n = fitness.size();
  std::vector<std::size_t> out;
  out.reserve(count);
  if (n == 0) return out;
  std::vector<double> weights = fitness;
  if (options.selection == Selection::rank) {
    // Weight = rank, 1 for the worst ... n for the best (ties by index).
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return fitness[a] < fitness[b]; });
    for (std::size_t r = 0; r < n; ++r) weights[order[r]] = static_cast<double>(r + 1);
  }
  if (options.selection == Selection::tournament) {
    const std::size_t k = static_cast<std::size_t>(std::max(1, options.tournament_size));
    for (std::size_t c = 0; c < count; ++c) {
      std::size_t winner = uniform_index(rng, n);
      for (std::size_t t = 1; t < k; ++t) {
        const std::size_t other = uniform_index(rng, n);
        if (fitness[other] > fitness[winner] || (fitness[other] == fitness[winner] && other < winner)) winner = other;
      }
      out.push_back(winner);
    }
    return out;
  }
  std::vector<double> cumulative(n);
  std::partial_sum(weights.begin(), weights.end(), cumulative.begin());
  const double total = cumulative.back();
  if (!(total > 0.0)) {
    for (std::size_t c = 0; c < count; ++c) out.push_back(uniform_index(rng, n));
    return out;
  }
  if (options.selection == Selection::stochastic_universal) {
    // One spin, `count` evenly spaced pointers.
    const double spacing = total / static_cast<double>(count);
    const double start = uniform01(rng) * spacing;
    for (std::size_t c = 0; c < count; ++c) out.push_back(spin(cumulative, start + static_cast<double>(c) * spacing));
    return out;
  }
  // Roulette (and rank, with rank weights): `count` spins.
  for (std::size_t c = 0; c < count; ++c) out.push_back(spin(cumulative, uniform01(rng) * total));
  return out;
}

std::pair<Genome::Bits, Genome::Bits> cross(const Genome::Bits& a, const Genome::Bits& b, Crossover kind,
                                            GaRandom& rng) {
  constexpr std::size_t n = Genome::kBits;
  Genome::Bits mask;  // 1: the first child takes the bit from b
  if (kind == Crossover::uniform) {
    for (std::size_t i = 0; i < n; ++i) mask.set(i, (rng() >> 63) != 0);
  } else {
    std::size_t from = 1 + uniform_index(rng, n - 1), to = n;  // cut points in [1, n-1]
    if (kind == Crossover::two_point) {
      std::size_t second = 1 + uniform_index(rng, n - 1);
      while (second == from) second = 1 + uniform_index(rng, n - 1);
      to = std::max(from, second);
      from = std::min(from, second);
    }
    for (std::size_t i = from; i < to; ++i) mask.set(i);
  }
  return {(a & ~mask) | (b & mask), (b & ~mask) | (a & mask)};
}

void mutate(Genome::Bits& bits, const GaOptions& options, GaRandom& rng) {
  constexpr std::size_t n = Genome::kBits;
  if (options.bit_flip_probability > 0.0)
    for (std::size_t i = 0; i < n; ++i)
      if (uniform01(rng) < options.bit_flip_probability) bits.flip(i);
  if (uniform01(rng) < options.interchange_probability) {
    const std::size_t i = uniform_index(rng, n), j = uniform_index(rng, n);
    const bool bi = bits[i];
    bits.set(i, bits[j]);
    bits.set(j, bi);
  }
  if (uniform01(rng) < options.reverse_probability) {
    const std::size_t i = uniform_index(rng, n - 1);
    const bool bi = bits[i];
    bits.set(i, bits[i + 1]);
    bits.set(i + 1, bi);
  }
}

}  // namespace facadeslam::semantics
