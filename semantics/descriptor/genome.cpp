#include "semantics/descriptor/genome.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <stdexcept>

#include "core/util/error.hpp"

namespace facadeslam::semantics {
namespace {

enum Field { kColour, kRadius, kKernel, kSigma, kDepth, kSize, kSplit, kCannyKernel, kCannyLow, kGradient };

int read_field(const Genome::Bits& bits, Field f) {
  const ParameterField& field = kParameterFields[static_cast<std::size_t>(f)];
  int x = 0;
  for (int i = 0; i < field.bit_count; ++i)
    if (bits.test(static_cast<std::size_t>(field.first_bit + i))) x |= 1 << i;
  return x;
}

void write_field(Genome::Bits& bits, Field f, int x) {
  const ParameterField& field = kParameterFields[static_cast<std::size_t>(f)];
  for (int i = 0; i < field.bit_count; ++i)
    bits.set(static_cast<std::size_t>(field.first_bit + i), ((x >> i) & 1) != 0);
}

template <typename T, std::size_t N>
int index_in(const std::array<T, N>& table, T value) {
  for (std::size_t i = 0; i < N; ++i) {
    if constexpr (std::is_floating_point_v<T>) {
      if (std::abs(table[i] - value) < 1e-9) return static_cast<int>(i);
    } else if (table[i] == value) {
      return static_cast<int>(i);
    }
  }
  throw std::logic_error("value missing from its table after validate()");
}

template <typename T, std::size_t N>
T entry(const std::array<T, N>& table, int index) {
  return table[static_cast<std::size_t>(index)];
}

void require_index(int index) {
  if (index < 0 || index >= Genome::kBits)
    throw std::out_of_range("genome bit " + std::to_string(index) + " is outside 0..210");
}

// Table 5.4 of the thesis, one string per module in module order; the
// per-channel / per-statistic groups the thesis separates by commas are
// simply concatenated (see module_layout.hpp for the value order).
constexpr std::array<std::string_view, kModuleCount> kThesisActivation{
    "11",  // position: x, y
    "101"
    "110",  // mean (c0, c2), std (c0, c1)
    "011"
    "000"
    "110",  // eta 2nd order
    "1001"
    "0100"
    "0101",  // eta 3rd order
    "00101"
    "00001"
    "01110",  // eta 4th order
    "100111"
    "100101"
    "111000",  // eta 5th order
    "0100101"
    "1011101"
    "0001111",  // Hu
    "101"
    "101",  // Gevers l: mean (l1, l3), std (l1, l3)
    "100"
    "111",  // Gevers c: mean (c1), std (c1, c2, c3)
    "10"
    "01",  // Geusebroek: mean H, std C
    "0101000110"
    "1010010100"
    "1000000110",  // affine moment invariants
    "1"
    "1",  // edge distance mean, std
    "100"
    "110"
    "100",  // singular values
    "01110"
    "01010"
    "01110"  // gradient region means per channel
    "0010111101"
    "1010110100"
    "0001011010",  // their differences per channel
};

}  // namespace

DescriptorParams Genome::decode() const {
  DescriptorParams p;
  p.colour_space = entry(kColourSpaces, read_field(bits_, kColour));
  p.patch_radius = entry(kPatchRadii, read_field(bits_, kRadius));
  p.gaussian_kernel = entry(kGaussianKernels, read_field(bits_, kKernel));
  p.gaussian_sigma = entry(kGaussianSigmas, read_field(bits_, kSigma));
  p.forest_depth = entry(kForestDepths, read_field(bits_, kDepth));
  p.forest_size = entry(kForestSizes, read_field(bits_, kSize));
  p.split_variables = entry(kSplitVariables, read_field(bits_, kSplit));
  p.canny_kernel = entry(kCannyKernels, read_field(bits_, kCannyKernel));
  p.canny_low_threshold = entry(kCannyLowThresholds, read_field(bits_, kCannyLow));
  p.gradient_operator = entry(kGradientOperators, read_field(bits_, kGradient));
  for (int i = 0; i < kActivationBits; ++i)
    p.activation.set(static_cast<std::size_t>(i), bits_.test(static_cast<std::size_t>(kParameterBits + i)));
  return p;
}

Genome Genome::encode(const DescriptorParams& p) {
  validate(p);
  Bits bits;
  write_field(bits, kColour, index_in(kColourSpaces, p.colour_space));
  write_field(bits, kRadius, index_in(kPatchRadii, p.patch_radius));
  write_field(bits, kKernel, index_in(kGaussianKernels, p.gaussian_kernel));
  write_field(bits, kSigma, index_in(kGaussianSigmas, p.gaussian_sigma));
  write_field(bits, kDepth, index_in(kForestDepths, p.forest_depth));
  write_field(bits, kSize, index_in(kForestSizes, p.forest_size));
  write_field(bits, kSplit, index_in(kSplitVariables, p.split_variables));
  write_field(bits, kCannyKernel, index_in(kCannyKernels, p.canny_kernel));
  write_field(bits, kCannyLow, index_in(kCannyLowThresholds, p.canny_low_threshold));
  write_field(bits, kGradient, index_in(kGradientOperators, p.gradient_operator));
  for (int i = 0; i < kActivationBits; ++i)
    bits.set(static_cast<std::size_t>(kParameterBits + i), p.activation.test(static_cast<std::size_t>(i)));
  return Genome(bits);
}

bool Genome::bit(int index) const {
  require_index(index);
  return bits_.test(static_cast<std::size_t>(index));
}

void Genome::set_bit(int index, bool value) {
  require_index(index);
  bits_.set(static_cast<std::size_t>(index), value);
}

int Genome::active_value_count() const {
  int n = 0;
  for (int i = kParameterBits; i < kBits; ++i) n += bits_.test(static_cast<std::size_t>(i)) ? 1 : 0;
  return n;
}

std::string Genome::to_string() const {
  std::string text(kBits, '0');
  for (int i = 0; i < kBits; ++i)
    if (bits_.test(static_cast<std::size_t>(i))) text[static_cast<std::size_t>(i)] = '1';
  return text;
}

Genome Genome::parse(std::string_view text, std::string_view where) {
  const auto is_space = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  while (!text.empty() && is_space(text.front())) text.remove_prefix(1);
  while (!text.empty() && is_space(text.back())) text.remove_suffix(1);
  const std::string prefix = std::string(where) + ": ";
  if (text.size() != static_cast<std::size_t>(kBits))
    throw Error(prefix + "a genome has 211 characters '0'/'1' (26 parameter bits + 185 activation bits), got " +
                std::to_string(text.size()));
  Bits bits;
  for (int i = 0; i < kBits; ++i) {
    const char c = text[static_cast<std::size_t>(i)];
    if (c != '0' && c != '1') {
      const std::string shown = std::isprint(static_cast<unsigned char>(c))
                                    ? std::string(1, c)
                                    : "byte " + std::to_string(static_cast<unsigned char>(c));
      throw Error(prefix + "genome character " + std::to_string(i) + " (" + genome_bit_owner(i) + ") is '" + shown +
                  "'; only '0' and '1' are allowed");
    }
    bits.set(static_cast<std::size_t>(i), c == '1');
  }
  return Genome(bits);
}

Genome Genome::thesis_best() {
  DescriptorParams p;
  p.colour_space = ColourSpace::xyz;
  p.patch_radius = 10;
  p.gaussian_kernel = 7;
  p.gaussian_sigma = 1.5;
  p.forest_size = 100;
  p.forest_depth = 35;
  p.split_variables = 16;
  p.canny_kernel = 5;
  p.canny_low_threshold = 65;
  p.gradient_operator = GradientOperator::sobel;
  std::size_t value = 0;
  for (const std::string_view module : kThesisActivation)
    for (const char c : module) p.activation.set(value++, c == '1');
  if (value != static_cast<std::size_t>(kValueCount))
    throw std::logic_error("thesis activation table does not cover the 185 values");
  return encode(p);
}

std::string genome_bit_owner(int index) {
  require_index(index);
  for (const ParameterField& f : kParameterFields)
    if (index >= f.first_bit && index < f.first_bit + f.bit_count) return "parameter field " + std::string(f.name);
  const int value = index - Genome::kParameterBits;
  return "activation of " + value_name(value) + " in module " + std::string(module_name(module_of_value(value)));
}

}  // namespace facadeslam::semantics
