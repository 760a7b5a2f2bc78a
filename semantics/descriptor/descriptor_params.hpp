#pragma once
// The decoded genome: every parameter the descriptor, its preprocessing and
// the forest need, by name, plus which of the 185 values are active.
// The value tables are those of the thesis (IV.4.1) and docs/design.md; a genome
// field of n bits indexes its table with x = sum b_i 2^i (thesis eq. IV.1).
#include <array>
#include <optional>
#include <string>
#include <string_view>

#include "semantics/descriptor/module_layout.hpp"

namespace facadeslam::semantics {

enum class ColourSpace : int { rgb, lab, luv, xyz, hsv, hls, ycrcb, opponent };
enum class GradientOperator : int { sobel, scharr };

// The parameter tables, in genome order (index = decoded field value).
inline constexpr std::array<ColourSpace, 8> kColourSpaces{ColourSpace::rgb,   ColourSpace::lab,     ColourSpace::luv,
                                                          ColourSpace::xyz,   ColourSpace::hsv,     ColourSpace::hls,
                                                          ColourSpace::ycrcb, ColourSpace::opponent};
inline constexpr std::array<int, 8> kPatchRadii{3, 4, 5, 6, 7, 8, 9, 10};
inline constexpr std::array<int, 8> kGaussianKernels{1, 3, 5, 7, 9, 11, 13, 15};
inline constexpr std::array<double, 8> kGaussianSigmas{0.8, 1.1, 1.5, 3, 6, 12, 24, 30};
inline constexpr std::array<int, 8> kForestDepths{5, 10, 15, 20, 25, 30, 35, 40};
inline constexpr std::array<int, 8> kForestSizes{40, 50, 60, 70, 80, 100, 120, 140};
inline constexpr std::array<int, 8> kSplitVariables{4, 8, 12, 16, 20, 25, 30, 35};
inline constexpr std::array<int, 2> kCannyKernels{3, 5};
inline constexpr std::array<int, 8> kCannyLowThresholds{15, 25, 35, 45, 55, 65, 75, 85};
inline constexpr std::array<GradientOperator, 2> kGradientOperators{GradientOperator::sobel, GradientOperator::scharr};
inline constexpr int kMaxPatchRadius = 10;

struct DescriptorParams {
  ColourSpace colour_space = ColourSpace::rgb;
  int patch_radius = 3;     // patch is (2r+1) x (2r+1)
  int gaussian_kernel = 1;  // 1 = no blur
  double gaussian_sigma = 0.8;
  int forest_depth = 5;
  int forest_size = 40;
  int split_variables = 4;
  int canny_kernel = 3;  // Canny's Sobel aperture
  int canny_low_threshold = 15;
  GradientOperator gradient_operator = GradientOperator::sobel;
  ActivationMask activation;  // bit i = value i of the 185 (module_layout.hpp)

  int canny_high_threshold() const { return 3 * canny_low_threshold; }  // thesis: 3 : 1
  int active_value_count() const { return static_cast<int>(activation.count()); }
  bool module_active(Module m) const { return module_bits(activation, m) != 0; }

  friend bool operator==(const DescriptorParams&, const DescriptorParams&) = default;
};

// "RGB", "Lab", "Luv", "XYZ", "HSV", "HLS", "YCrCb", "OpponentRGB".
std::string_view colour_space_name(ColourSpace space);
std::optional<ColourSpace> parse_colour_space(std::string_view name);
// "Sobel", "Scharr".
std::string_view gradient_operator_name(GradientOperator op);
std::optional<GradientOperator> parse_gradient_operator(std::string_view name);

// Throws Error naming the first field whose value is not in its table
// (a genome can only hold table values, so params built by hand must too).
void validate(const DescriptorParams& params);

}  // namespace facadeslam::semantics
