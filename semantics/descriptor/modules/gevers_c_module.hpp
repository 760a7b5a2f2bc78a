#pragma once
#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// Module 9: mean and sigma of Gevers c1, c2, c3: [mean c1..c3, std c1..c3].
void gevers_c_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
