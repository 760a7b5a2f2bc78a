#include "semantics/descriptor/modules/affine_invariants_module.hpp"

#include <cmath>

#include <opencv2/core.hpp>

namespace facadeslam::semantics {

int affine_invariant_order(int k) {
  static constexpr int kOrders[10] = {2, 3, 3, 3, 4, 4, 4, 4, 4, 5};
  CV_Assert(k >= 1 && k <= 10);
  return kOrders[k - 1];
}

double affine_invariant(const PatchMoments& m, int k) {
  const double m00 = m.mass();
  if (!(m00 > 0.0)) return 0.0;
  const auto u = [&](int p, int q) { return m.mu[p][q]; };
  const double u20 = u(2, 0), u11 = u(1, 1), u02 = u(0, 2);
  switch (k) {
    case 1: return (u20 * u02 - u11 * u11) / m.mass_powers[4];
    case 2: {
      const double u30 = u(3, 0), u21 = u(2, 1), u12 = u(1, 2), u03 = u(0, 3);
      return (-u30 * u30 * u03 * u03 + 6 * u30 * u21 * u12 * u03 - 4 * u30 * u12 * u12 * u12 -
              4 * u21 * u21 * u21 * u03 + 3 * u21 * u21 * u12 * u12) /
             m.mass_powers[10];
    }
    case 3: {
      const double u30 = u(3, 0), u21 = u(2, 1), u12 = u(1, 2), u03 = u(0, 3);
      return (u20 * u21 * u03 - u20 * u12 * u12 - u11 * u30 * u03 + u11 * u21 * u12 + u02 * u30 * u12 -
              u02 * u21 * u21) /
             m.mass_powers[7];
    }
    case 4: {
      const double u30 = u(3, 0), u21 = u(2, 1), u12 = u(1, 2), u03 = u(0, 3);
      const double a = u20, b = u11, c = u02;
      return (-a * a * a * u03 * u03 + 6 * a * a * b * u12 * u03 - 3 * a * a * c * u12 * u12 -
              6 * a * b * b * u21 * u03 - 6 * a * b * b * u12 * u12 + 12 * a * b * c * u21 * u12 -
              3 * a * c * c * u21 * u21 + 2 * b * b * b * u30 * u03 + 6 * b * b * b * u21 * u12 -
              6 * b * b * c * u30 * u12 - 6 * b * b * c * u21 * u21 + 6 * b * c * c * u30 * u21 -
              c * c * c * u30 * u30) /
             m.mass_powers[11];
    }
    case 5: {
      const double u40 = u(4, 0), u31 = u(3, 1), u22 = u(2, 2), u13 = u(1, 3), u04 = u(0, 4);
      return (u40 * u04 - 4 * u31 * u13 + 3 * u22 * u22) / m.mass_powers[6];
    }
    case 6: {
      const double u40 = u(4, 0), u31 = u(3, 1), u22 = u(2, 2), u13 = u(1, 3), u04 = u(0, 4);
      return (u40 * u22 * u04 - u40 * u13 * u13 - u31 * u31 * u04 + 2 * u31 * u22 * u13 - u22 * u22 * u22) /
             m.mass_powers[9];
    }
    case 7: {
      const double u40 = u(4, 0), u31 = u(3, 1), u22 = u(2, 2), u13 = u(1, 3), u04 = u(0, 4);
      return (u20 * u20 * u04 - 4 * u20 * u11 * u13 + 2 * u20 * u02 * u22 + 4 * u11 * u11 * u22 - 4 * u11 * u02 * u31 +
              u02 * u02 * u40) /
             m.mass_powers[7];
    }
    case 8: {
      const double u40 = u(4, 0), u31 = u(3, 1), u22 = u(2, 2), u13 = u(1, 3), u04 = u(0, 4);
      const double a = u20, b = u11, c = u02;
      return (a * a * u22 * u04 - a * a * u13 * u13 - 2 * a * b * u31 * u04 + 2 * a * b * u22 * u13 +
              a * c * u40 * u04 - 2 * a * c * u31 * u13 + a * c * u22 * u22 + 4 * b * b * u31 * u13 -
              4 * b * b * u22 * u22 - 2 * b * c * u40 * u13 + 2 * b * c * u31 * u22 + c * c * u40 * u22 -
              c * c * u31 * u31) /
             m.mass_powers[10];
    }
    case 9: {
      const double u30 = u(3, 0), u21 = u(2, 1), u12 = u(1, 2), u03 = u(0, 3);
      const double u40 = u(4, 0), u31 = u(3, 1), u22 = u(2, 2), u13 = u(1, 3), u04 = u(0, 4);
      return (u30 * u30 * u12 * u12 * u04 - 2 * u30 * u30 * u12 * u03 * u13 + u30 * u30 * u03 * u03 * u22 -
              2 * u30 * u21 * u21 * u12 * u04 + 2 * u30 * u21 * u21 * u03 * u13 + 2 * u30 * u21 * u12 * u12 * u13 -
              2 * u30 * u21 * u03 * u03 * u31 - 2 * u30 * u12 * u12 * u12 * u22 + 2 * u30 * u12 * u12 * u03 * u31 +
              u21 * u21 * u21 * u21 * u04 - 2 * u21 * u21 * u21 * u12 * u13 - 2 * u21 * u21 * u21 * u03 * u22 +
              3 * u21 * u21 * u12 * u12 * u22 + 2 * u21 * u21 * u12 * u03 * u31 + u21 * u21 * u03 * u03 * u40 -
              2 * u21 * u12 * u12 * u12 * u31 - 2 * u21 * u12 * u12 * u03 * u40 + u12 * u12 * u12 * u12 * u40) /
             m.mass_powers[13];
    }
    case 10: {
      const double u50 = u(5, 0), u41 = u(4, 1), u32 = u(3, 2), u23 = u(2, 3), u14 = u(1, 4), u05 = u(0, 5);
      return (-u50 * u50 * u05 * u05 + 10 * u50 * u41 * u14 * u05 - 4 * u50 * u32 * u23 * u05 -
              16 * u50 * u32 * u14 * u14 + 12 * u50 * u23 * u23 * u14 - 16 * u41 * u41 * u23 * u05 -
              9 * u41 * u41 * u14 * u14 + 12 * u41 * u32 * u32 * u05 + 76 * u41 * u32 * u23 * u14 -
              48 * u41 * u23 * u23 * u23 - 48 * u32 * u32 * u32 * u14 + 32 * u32 * u32 * u23 * u23) /
             m.mass_powers[14];
    }
    default: CV_Error(cv::Error::StsOutOfRange, "affine invariant index must be 1..10");
  }
}

void affine_invariants_module(const ModuleContext& context, std::uint64_t bits, float* values) {
  for (int c = 0; c < 3; ++c)
    for (int k = 0; k < 10; ++k)
      if (bit_set(bits, 10 * c + k))
        values[10 * c + k] = static_cast<float>(affine_invariant(context.moments[static_cast<std::size_t>(c)], k + 1));
}

}  // namespace facadeslam::semantics
