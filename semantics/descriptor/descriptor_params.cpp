#include "semantics/descriptor/descriptor_params.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "core/util/error.hpp"

namespace facadeslam::semantics {
namespace {

constexpr std::array<std::string_view, 8> kColourSpaceNames{"RGB", "Lab", "Luv",   "XYZ",
                                                            "HSV", "HLS", "YCrCb", "OpponentRGB"};
constexpr std::array<std::string_view, 2> kGradientNames{"Sobel", "Scharr"};

template <typename T, std::size_t N>
void require_in_table(const char* field, T value, const std::array<T, N>& table) {
  const bool found = std::any_of(table.begin(), table.end(), [&](T t) {
    if constexpr (std::is_floating_point_v<T>)
      return std::abs(t - value) < 1e-9;
    else
      return t == value;
  });
  if (found) return;
  std::ostringstream msg;
  msg << "descriptor parameter " << field << " = " << value << " is not one of";
  for (const T t : table) msg << ' ' << t;
  throw Error(msg.str());
}

}  // namespace

std::string_view colour_space_name(ColourSpace space) { return kColourSpaceNames[static_cast<std::size_t>(space)]; }

std::optional<ColourSpace> parse_colour_space(std::string_view name) {
  for (std::size_t i = 0; i < kColourSpaceNames.size(); ++i)
    if (kColourSpaceNames[i] == name) return static_cast<ColourSpace>(i);
  return std::nullopt;
}

std::string_view gradient_operator_name(GradientOperator op) { return kGradientNames[static_cast<std::size_t>(op)]; }

std::optional<GradientOperator> parse_gradient_operator(std::string_view name) {
  for (std::size_t i = 0; i < kGradientNames.size(); ++i)
    if (kGradientNames[i] == name) return static_cast<GradientOperator>(i);
  return std::nullopt;
}

void validate(const DescriptorParams& p) {
  if (static_cast<int>(p.colour_space) < 0 || static_cast<int>(p.colour_space) >= 8)
    throw Error("descriptor parameter colour_space holds an unknown colour space");
  require_in_table("patch_radius", p.patch_radius, kPatchRadii);
  require_in_table("gaussian_kernel", p.gaussian_kernel, kGaussianKernels);
  require_in_table("gaussian_sigma", p.gaussian_sigma, kGaussianSigmas);
  require_in_table("forest_depth", p.forest_depth, kForestDepths);
  require_in_table("forest_size", p.forest_size, kForestSizes);
  require_in_table("split_variables", p.split_variables, kSplitVariables);
  require_in_table("canny_kernel", p.canny_kernel, kCannyKernels);
  require_in_table("canny_low_threshold", p.canny_low_threshold, kCannyLowThresholds);
  if (static_cast<int>(p.gradient_operator) < 0 || static_cast<int>(p.gradient_operator) >= 2)
    throw Error("descriptor parameter gradient_operator holds an unknown operator");
}

}  // namespace facadeslam::semantics
