#include "semantics/descriptor/modules/gevers_l_module.hpp"

#include "semantics/descriptor/modules/plane_statistics.hpp"

namespace facadeslam::semantics {

void gevers_l_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  static constexpr PlaneId kPlanes[3] = {PlaneId::gevers_l1, PlaneId::gevers_l2, PlaneId::gevers_l3};
  mean_std_values(context, kPlanes, 3, bits, values);
}

}  // namespace facadeslam::semantics
