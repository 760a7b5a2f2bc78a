#include "semantics/descriptor/modules/hu_module.hpp"

namespace facadeslam::semantics {

std::array<double, 7> hu_invariants(const PatchMoments& m) {
  const double n20 = m.eta(2, 0), n11 = m.eta(1, 1), n02 = m.eta(0, 2);
  const double n30 = m.eta(3, 0), n21 = m.eta(2, 1), n12 = m.eta(1, 2), n03 = m.eta(0, 3);
  const double a = n30 + n12, b = n21 + n03;          // the two "sum" terms
  const double c = n30 - 3 * n12, d = 3 * n21 - n03;  // the two "difference" terms
  std::array<double, 7> phi{};
  phi[0] = n20 + n02;
  phi[1] = (n20 - n02) * (n20 - n02) + 4 * n11 * n11;
  phi[2] = c * c + d * d;
  phi[3] = a * a + b * b;
  phi[4] = c * a * (a * a - 3 * b * b) + d * b * (3 * a * a - b * b);
  phi[5] = (n20 - n02) * (a * a - b * b) + 4 * n11 * a * b;
  phi[6] = d * a * (a * a - 3 * b * b) - c * b * (3 * a * a - b * b);
  return phi;
}

void hu_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  for (int c = 0; c < 3; ++c) {
    if (((bits >> (7 * c)) & 0x7F) == 0) continue;
    const std::array<double, 7> phi = hu_invariants(context.moments[static_cast<std::size_t>(c)]);
    for (int k = 0; k < 7; ++k)
      if (bit_set(bits, 7 * c + k)) values[7 * c + k] = static_cast<float>(phi[static_cast<std::size_t>(k)]);
  }
}

}  // namespace facadeslam::semantics
