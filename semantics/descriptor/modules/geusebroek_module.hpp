#pragma once
#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// Module 10: mean and sigma of Geusebroek H and C: [mean H, mean C, std H, std C].
void geusebroek_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
