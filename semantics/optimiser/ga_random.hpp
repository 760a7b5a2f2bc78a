#pragma once
// The optimiser's random numbers: a std::mt19937_64 (its state can be saved
// in a checkpoint as text and restored exactly) and draws made here rather
// than through std:: distributions, whose results the standard leaves to the
// library: a run, and a resumed run, give the same genomes everywhere.
#include <cstdint>
#include <random>

namespace facadeslam::semantics {

using GaRandom = std::mt19937_64;

// In [0, 1), 53 random bits.
inline double uniform01(GaRandom& rng) { return static_cast<double>(rng() >> 11) * 0x1.0p-53; }

// In [0, n), n >= 1: the top 53 bits scaled (no modulo bias worth the name
// for the population- and genome-sized n used here).
inline std::size_t uniform_index(GaRandom& rng, std::size_t n) {
  const auto i = static_cast<std::size_t>(uniform01(rng) * static_cast<double>(n));
  return i < n ? i : n - 1;
}

}  // namespace facadeslam::semantics
