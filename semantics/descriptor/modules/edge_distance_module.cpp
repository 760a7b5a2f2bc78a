#include "semantics/descriptor/modules/edge_distance_module.hpp"

#include "semantics/descriptor/modules/plane_statistics.hpp"

namespace facadeslam::semantics {

void edge_distance_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  static constexpr PlaneId kPlanes[1] = {PlaneId::edge_distance};
  mean_std_values(context, kPlanes, 1, bits, values);
}

}  // namespace facadeslam::semantics
