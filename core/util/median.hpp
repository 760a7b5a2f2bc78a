#pragma once
// The median of a sample (the upper one of an even count), for timings and
// robust scales; 0 for an empty sample.
#include <algorithm>
#include <cstddef>
#include <vector>

namespace facadeslam {

inline double median(std::vector<double> values) {
  if (values.empty()) return 0.0;
  const auto middle = values.begin() + static_cast<std::ptrdiff_t>(values.size() / 2);
  std::nth_element(values.begin(), middle, values.end());
  return *middle;
}

}  // namespace facadeslam
