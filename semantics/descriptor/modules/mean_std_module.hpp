#pragma once
#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// Module 2: mean and sigma of each colour channel over the patch:
// [mean c0, mean c1, mean c2, std c0, std c1, std c2].
void mean_std_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
