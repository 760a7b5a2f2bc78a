#include "semantics/descriptor/modules/central_moments_module.hpp"

namespace facadeslam::semantics {

void central_moments_module(int order, const ModuleContext& context, std::uint64_t bits, float* values) {
  const int per_channel = order + 1;
  for (int c = 0; c < 3; ++c) {
    const PatchMoments& m = context.moments[static_cast<std::size_t>(c)];
    for (int k = 0; k < per_channel; ++k) {
      const int i = c * per_channel + k;
      if (bit_set(bits, i)) values[i] = static_cast<float>(m.eta(order - k, k));
    }
  }
}

void moments2_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  central_moments_module(2, context, bits, values);
}
void moments3_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  central_moments_module(3, context, bits, values);
}
void moments4_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  central_moments_module(4, context, bits, values);
}
void moments5_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  central_moments_module(5, context, bits, values);
}

}  // namespace facadeslam::semantics
