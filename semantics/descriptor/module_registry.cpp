#include "semantics/descriptor/module_registry.hpp"

#include <array>

#include "semantics/descriptor/modules/affine_invariants_module.hpp"
#include "semantics/descriptor/modules/central_moments_module.hpp"
#include "semantics/descriptor/modules/edge_distance_module.hpp"
#include "semantics/descriptor/modules/geusebroek_module.hpp"
#include "semantics/descriptor/modules/gevers_c_module.hpp"
#include "semantics/descriptor/modules/gevers_l_module.hpp"
#include "semantics/descriptor/modules/gradient_angles_module.hpp"
#include "semantics/descriptor/modules/hu_module.hpp"
#include "semantics/descriptor/modules/mean_std_module.hpp"
#include "semantics/descriptor/modules/position_module.hpp"
#include "semantics/descriptor/modules/singular_values_module.hpp"

namespace facadeslam::semantics {

ModuleFunction module_function(Module m) {
  static constexpr std::array<ModuleFunction, kModuleCount> kFunctions{position_module,
                                                                       mean_std_module,
                                                                       moments2_module,
                                                                       moments3_module,
                                                                       moments4_module,
                                                                       moments5_module,
                                                                       hu_module,
                                                                       gevers_l_module,
                                                                       gevers_c_module,
                                                                       geusebroek_module,
                                                                       affine_invariants_module,
                                                                       edge_distance_module,
                                                                       singular_values_module,
                                                                       gradient_angles_module};
  return kFunctions[static_cast<std::size_t>(m)];
}

}  // namespace facadeslam::semantics
