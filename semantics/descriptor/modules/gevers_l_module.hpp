#pragma once
#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

// Module 8: mean and sigma of Gevers l1, l2, l3: [mean l1..l3, std l1..l3].
void gevers_l_module(const ModuleContext& context, std::uint64_t bits, float* values);

}  // namespace facadeslam::semantics
