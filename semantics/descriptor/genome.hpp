#pragma once
// The 211-bit genome of the modular descriptor (thesis IV.4.1, docs/design.md):
// 26 parameter bits in ten fields, then 185 activation bits, one per module
// value in module_layout.hpp order.
//
// Bit order: bit i of the genome is character i of its text form. A field of
// n bits b_0..b_(n-1) (b_0 first) selects entry x = sum b_i 2^i of its table
// (thesis eq. IV.1), so "110" selects entry 3.
#include <array>
#include <bitset>
#include <string>
#include <string_view>

#include "semantics/descriptor/descriptor_params.hpp"

namespace facadeslam::semantics {

struct ParameterField {
  std::string_view name;
  int first_bit;
  int bit_count;
};

// The ten parameter fields, in genome order.
inline constexpr std::array<ParameterField, 10> kParameterFields{{
    {"colour_space", 0, 3},
    {"patch_radius", 3, 3},
    {"gaussian_kernel", 6, 3},
    {"gaussian_sigma", 9, 3},
    {"forest_depth", 12, 3},
    {"forest_size", 15, 3},
    {"split_variables", 18, 3},
    {"canny_kernel", 21, 1},
    {"canny_low_threshold", 22, 3},
    {"gradient_operator", 25, 1},
}};

class Genome {
 public:
  static constexpr int kParameterBits = 26;
  static constexpr int kActivationBits = kValueCount;
  static constexpr int kBits = kParameterBits + kActivationBits;
  static_assert(kBits == 211);
  using Bits = std::bitset<kBits>;

  // All bits 0: RGB, radius 3, no blur, ..., and no active value.
  Genome() = default;
  explicit Genome(const Bits& bits) : bits_(bits) {}

  // Every bit string decodes (each table has 2^bits entries).
  DescriptorParams decode() const;
  // Throws Error when a parameter is not a table value (see validate()).
  static Genome encode(const DescriptorParams& params);

  const Bits& bits() const { return bits_; }
  bool bit(int index) const;
  void set_bit(int index, bool value);
  int active_value_count() const;

  // 211 characters '0'/'1', bit 0 first.
  std::string to_string() const;
  // Accepts exactly 211 '0'/'1' characters, optionally surrounded by
  // whitespace. Errors name the length or the first bad character and the
  // field it falls in; `where` (a file name, "--genome") starts the message.
  static Genome parse(std::string_view text, std::string_view where = "genome");

  // The thesis' optimised genome (Tables 5.3-5.5): XYZ, radius 10, kernel 7,
  // sigma 1.5, 100 trees of depth 35, 16 split variables, Canny 5 / 65,
  // Sobel, and the 93 active values listed bit by bit in Table 5.4.
  static Genome thesis_best();

  friend bool operator==(const Genome&, const Genome&) = default;

 private:
  Bits bits_;
};

// The name of the parameter field or module a genome bit belongs to.
std::string genome_bit_owner(int index);

}  // namespace facadeslam::semantics
