#include "tracker/tukey.hpp"

#include <algorithm>

namespace facadeslam {

double robust_sigma_squared(std::span<double> squared_errors, double min_sigma_squared,
                            double median_to_sigma_squared) {
  if (squared_errors.empty()) return min_sigma_squared;
  // Upper median for even sizes, as PTAM (v[n / 2] of the sorted values).
  const auto middle = squared_errors.begin() + static_cast<std::ptrdiff_t>(squared_errors.size() / 2);
  std::nth_element(squared_errors.begin(), middle, squared_errors.end());
  return std::max(min_sigma_squared, median_to_sigma_squared * *middle);
}

}  // namespace facadeslam
