#pragma once
// The module bank of the modular descriptor (thesis IV.4.3): 14 modules
// producing 185 values in a fixed order. The activation part of the genome
// has one bit per value in exactly this order, so this table is the contract
// between the genome, the extractor, trained forests and saved genomes.
#include <array>
#include <bitset>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace facadeslam::semantics {

enum class Module : int {
  position,           // normalised x, y of the keypoint                          2
  mean_std,           // mean, sigma of each colour channel                       6
  moments2,           // eta20 eta11 eta02 per channel                            9
  moments3,           // eta30 eta21 eta12 eta03 per channel                     12
  moments4,           // eta40 .. eta04 per channel                              15
  moments5,           // eta50 .. eta05 per channel                              18
  hu,                 // Hu phi1..phi7 per channel                               21
  gevers_l,           // mean, sigma of Gevers l1 l2 l3                           6
  gevers_c,           // mean, sigma of Gevers c1 c2 c3                           6
  geusebroek,         // mean, sigma of Geusebroek H and C                        4
  affine_invariants,  // Flusser-Suk I1..I10 per channel                         30
  edge_distance,      // mean, sigma of the distance to the nearest Canny edge    2
  singular_values,    // three largest singular values per channel                9
  gradient_angles,    // 5 region means per channel + 10 differences per channel 45
};

inline constexpr int kModuleCount = 14;

inline constexpr std::array<int, kModuleCount> kModuleSizes{2, 6, 9, 12, 15, 18, 21, 6, 6, 4, 30, 2, 9, 45};

inline constexpr int kValueCount = [] {
  int total = 0;
  for (const int size : kModuleSizes) total += size;
  return total;
}();
static_assert(kValueCount == 185, "the thesis' module bank has 185 values (docs/design.md)");

// Index of a module's first value in the 185-value layout.
inline constexpr std::array<int, kModuleCount> kModuleOffsets = [] {
  std::array<int, kModuleCount> offsets{};
  int offset = 0;
  for (int m = 0; m < kModuleCount; ++m) {
    offsets[static_cast<std::size_t>(m)] = offset;
    offset += kModuleSizes[static_cast<std::size_t>(m)];
  }
  return offsets;
}();

// The largest module fits a 64-bit per-module mask.
static_assert(kModuleSizes[13] == 45 && kModuleSizes[13] <= 64);

constexpr int module_size(Module m) { return kModuleSizes[static_cast<std::size_t>(m)]; }
constexpr int module_offset(Module m) { return kModuleOffsets[static_cast<std::size_t>(m)]; }

// One bit per value (bit i = value i of the 185), as in the genome.
using ActivationMask = std::bitset<kValueCount>;

// The module's slice of `mask`: bit i = the module's i-th value.
std::uint64_t module_bits(const ActivationMask& mask, Module m);

// `mask` with only the values of `modules` kept.
ActivationMask restricted_to(const ActivationMask& mask, std::span<const Module> modules);

// Modules whose values are means and sigmas of planes: extraction sums one
// strip per plane they read (their column sums are shared), and the GA's
// cost model counts it so.
inline constexpr std::array<Module, 5> kStatisticsModules = {Module::mean_std, Module::gevers_l, Module::gevers_c,
                                                             Module::geusebroek, Module::edge_distance};

// The module a value index (0..184) belongs to.
Module module_of_value(int value_index);

// Short snake_case module name ("gevers_l", "singular_values", ...).
std::string_view module_name(Module m);

// Stable names of the 185 values, e.g. "mean_c0", "eta21_c2", "hu3_c1",
// "mean_gevers_l2", "std_geusebroek_c", "ami10_c0", "sv2_c1",
// "angle12_c0", "angle00_minus_22_c2". Channels are c0, c1, c2 of the genome's
// colour space (e.g. X, Y, Z); gradient regions are 00 = whole patch,
// 11/12/21/22 = top-left/top-right/bottom-left/bottom-right quadrants.
const std::array<std::string, kValueCount>& value_names();
const std::string& value_name(int value_index);
std::optional<int> value_index(std::string_view name);

}  // namespace facadeslam::semantics
