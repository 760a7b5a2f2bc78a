#include "semantics/descriptor/modules/geusebroek_module.hpp"

#include "semantics/descriptor/modules/plane_statistics.hpp"

namespace facadeslam::semantics {

void geusebroek_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  static constexpr PlaneId kPlanes[2] = {PlaneId::geusebroek_h, PlaneId::geusebroek_c};
  mean_std_values(context, kPlanes, 2, bits, values);
}

}  // namespace facadeslam::semantics
