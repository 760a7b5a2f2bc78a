#include "semantics/descriptor/modules/position_module.hpp"

namespace facadeslam::semantics {

void position_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  if (bit_set(bits, 0)) values[0] = context.keypoint.x / static_cast<float>(context.image.image_size.width);
  if (bit_set(bits, 1)) values[1] = context.keypoint.y / static_cast<float>(context.image.image_size.height);
}

}  // namespace facadeslam::semantics
