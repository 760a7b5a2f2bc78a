#pragma once
#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// Module 1: keypoint x / image width, y / image height (thesis IV.4.3 (1)),
// so a forest can learn that sky is high and road low.
void position_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
