#include "semantics/descriptor/modules/mean_std_module.hpp"

#include "semantics/descriptor/modules/plane_statistics.hpp"

namespace facadeslam::semantics {

void mean_std_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  static constexpr PlaneId kPlanes[3] = {PlaneId::colour0, PlaneId::colour1, PlaneId::colour2};
  mean_std_values(context, kPlanes, 3, bits, values);
}

}  // namespace facadeslam::semantics
