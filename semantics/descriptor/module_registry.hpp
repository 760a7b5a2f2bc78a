#pragma once
// The function computing each module of the bank, indexed by Module.
#include "semantics/descriptor/modules/module_context.hpp"

namespace facadeslam::semantics {

ModuleFunction module_function(Module m);

}  // namespace facadeslam::semantics
