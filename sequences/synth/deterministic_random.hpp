#pragma once
// Random numbers that are the same on every machine and standard library:
// std::normal_distribution and friends are implementation-defined, and the
// promise "same seed, byte-identical sequence" must not depend on them.
// Everything here is built on the SplitMix64 mixing function, used as a
// counter-based generator: hash(seed, a, b, ...) -> 64 random bits, so a
// value depends only on its coordinates (frame, pixel, channel), never on how
// many values were drawn before it.
#include <cmath>
#include <cstdint>
#include <numbers>

namespace facadeslam::synth {

// SplitMix64's finaliser (Steele, Lea & Flood 2014).
constexpr std::uint64_t mix64(std::uint64_t x) {
  x += 0x9E3779B97F4A7C15ull;
  x = (x ^ (x >> 30)) * 0xBF58476D1CE4E5B9ull;
  x = (x ^ (x >> 27)) * 0x94D049BB133111EBull;
  return x ^ (x >> 31);
}

constexpr std::uint64_t hash64(std::uint64_t a) { return mix64(a); }
template <class... Rest>
constexpr std::uint64_t hash64(std::uint64_t a, std::uint64_t b, Rest... rest) {
  return hash64(mix64(a) ^ b, static_cast<std::uint64_t>(rest)...);
}

// 53 random bits -> [0, 1).
constexpr double uniform01(std::uint64_t bits) { return static_cast<double>(bits >> 11) * 0x1.0p-53; }

// A standard normal deviate from two hashes (Box-Muller).
inline double gaussian(std::uint64_t bits_a, std::uint64_t bits_b) {
  const double u1 = 1.0 - uniform01(bits_a);  // (0, 1]: log is finite
  const double u2 = uniform01(bits_b);
  return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
}

// A sequential generator for the few places that draw a handful of values
// in order (trajectory jitter phases, texture layout).
class SeededSequence {
 public:
  SeededSequence(std::uint64_t seed, std::uint64_t stream) : state_(hash64(seed, stream)) {}
  double uniform() { return uniform01(mix64(state_++)); }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }

 private:
  std::uint64_t state_;
};

}  // namespace facadeslam::synth
