#include "semantics/descriptor/module_layout.hpp"

#include <algorithm>
#include <stdexcept>
#include <vector>

namespace facadeslam::semantics {
namespace {

constexpr std::array<std::string_view, kModuleCount> kModuleNames{
    "position", "mean_std", "moments2",   "moments3",          "moments4",      "moments5",        "hu",
    "gevers_l", "gevers_c", "geusebroek", "affine_invariants", "edge_distance", "singular_values", "gradient_angles"};

std::string channel(int c) { return "_c" + std::to_string(c); }

// Appends mean_<x> for every stat name, then std_<x>: the thesis' genome
// strings (Table 5.4) group the means first, then the deviations.
void add_mean_std(std::vector<std::string>& names, const std::vector<std::string>& stats) {
  for (const auto& s : stats) names.push_back("mean_" + s);
  for (const auto& s : stats) names.push_back("std_" + s);
}

std::array<std::string, kValueCount> build_names() {
  std::vector<std::string> names;
  names.reserve(kValueCount);
  names.push_back("x_norm");
  names.push_back("y_norm");
  add_mean_std(names, {"c0", "c1", "c2"});
  // Moments are grouped by channel (Table 5.4: "011,000,110").
  const std::array<std::vector<std::string>, 4> orders{std::vector<std::string>{"20", "11", "02"},
                                                       {"30", "21", "12", "03"},
                                                       {"40", "31", "22", "13", "04"},
                                                       {"50", "41", "32", "23", "14", "05"}};
  for (const auto& order : orders)
    for (int c = 0; c < 3; ++c)
      for (const auto& pq : order) names.push_back("eta" + pq + channel(c));
  for (int c = 0; c < 3; ++c)
    for (int i = 1; i <= 7; ++i) names.push_back("hu" + std::to_string(i) + channel(c));
  add_mean_std(names, {"gevers_l1", "gevers_l2", "gevers_l3"});
  add_mean_std(names, {"gevers_c1", "gevers_c2", "gevers_c3"});
  add_mean_std(names, {"geusebroek_h", "geusebroek_c"});
  for (int c = 0; c < 3; ++c)
    for (int i = 1; i <= 10; ++i) names.push_back("ami" + std::to_string(i) + channel(c));
  add_mean_std(names, {"edge_distance"});
  for (int c = 0; c < 3; ++c)
    for (int i = 1; i <= 3; ++i) names.push_back("sv" + std::to_string(i) + channel(c));
  const std::array<std::string, 5> regions{"00", "11", "12", "21", "22"};
  for (int c = 0; c < 3; ++c)
    for (const auto& r : regions) names.push_back("angle" + r + channel(c));
  for (int c = 0; c < 3; ++c)
    for (std::size_t a = 0; a < regions.size(); ++a)
      for (std::size_t b = a + 1; b < regions.size(); ++b)
        names.push_back("angle" + regions[a] + "_minus_" + regions[b] + channel(c));
  if (names.size() != static_cast<std::size_t>(kValueCount))
    throw std::logic_error("value name table does not match the module layout");
  std::array<std::string, kValueCount> out;
  std::move(names.begin(), names.end(), out.begin());
  return out;
}

}  // namespace

std::uint64_t module_bits(const ActivationMask& mask, Module m) {
  std::uint64_t bits = 0;
  const int offset = module_offset(m);
  for (int i = 0; i < module_size(m); ++i)
    if (mask.test(static_cast<std::size_t>(offset + i))) bits |= std::uint64_t{1} << i;
  return bits;
}

ActivationMask restricted_to(const ActivationMask& mask, std::span<const Module> modules) {
  ActivationMask out;
  for (const Module m : modules)
    for (int i = 0; i < module_size(m); ++i) {
      const auto bit = static_cast<std::size_t>(module_offset(m) + i);
      out.set(bit, mask.test(bit));
    }
  return out;
}

Module module_of_value(int value_index) {
  if (value_index < 0 || value_index >= kValueCount)
    throw std::out_of_range("value index " + std::to_string(value_index) + " is outside 0..184");
  int m = kModuleCount - 1;
  while (kModuleOffsets[static_cast<std::size_t>(m)] > value_index) --m;
  return static_cast<Module>(m);
}

std::string_view module_name(Module m) { return kModuleNames[static_cast<std::size_t>(m)]; }

const std::array<std::string, kValueCount>& value_names() {
  static const std::array<std::string, kValueCount> names = build_names();
  return names;
}

const std::string& value_name(int value_index) {
  if (value_index < 0 || value_index >= kValueCount)
    throw std::out_of_range("value index " + std::to_string(value_index) + " is outside 0..184");
  return value_names()[static_cast<std::size_t>(value_index)];
}

std::optional<int> value_index(std::string_view name) {
  const auto& names = value_names();
  const auto it = std::find(names.begin(), names.end(), name);
  if (it == names.end()) return std::nullopt;
  return static_cast<int>(it - names.begin());
}

}  // namespace facadeslam::semantics
