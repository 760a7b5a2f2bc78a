#include "core/plot/ticks.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/util/error.hpp"

namespace facadeslam::plot {
namespace {

// The nice number near x: rounded to the nearest of 1, 2, 5, 10 (times a
// power of ten) when `round`, else the smallest of them that is >= x.
double nice_number(double x, bool round) {
  const double exponent = std::floor(std::log10(x));
  const double power = std::pow(10.0, exponent);
  const double fraction = x / power;
  double nice = 10.0;
  if (round) {
    if (fraction < 1.5)
      nice = 1.0;
    else if (fraction < 3.0)
      nice = 2.0;
    else if (fraction < 7.0)
      nice = 5.0;
  } else {
    if (fraction <= 1.0)
      nice = 1.0;
    else if (fraction <= 2.0)
      nice = 2.0;
    else if (fraction <= 5.0)
      nice = 5.0;
  }
  return nice * power;
}

}  // namespace

AxisTicks nice_ticks(double lo, double hi, int target_count) {
  if (!std::isfinite(lo) || !std::isfinite(hi))
    throw Error("plot axis: the data range must be finite, got [" + std::to_string(lo) + ", " + std::to_string(hi) +
                "]");
  if (target_count < 2) throw Error("plot axis: expected at least 2 ticks, got " + std::to_string(target_count));
  if (hi < lo) std::swap(lo, hi);
  // A single value (a constant series) still gets an axis around it.
  if (hi - lo <= 1e-12 * std::max(1.0, std::abs(lo))) {
    const double pad = lo == 0.0 ? 1.0 : 0.1 * std::abs(lo);
    lo -= pad;
    hi += pad;
  }

  AxisTicks ticks;
  const double span = nice_number(hi - lo, false);
  ticks.step = nice_number(span / (target_count - 1), true);
  // The small tolerance keeps a data end that is a tick (0.6 = 3 * 0.2 up to
  // rounding) from pulling in one more tick.
  const double first = std::floor(lo / ticks.step + 1e-9);
  const double last = std::ceil(hi / ticks.step - 1e-9);
  ticks.lo = first * ticks.step;
  ticks.hi = last * ticks.step;
  for (double k = first; k <= last + 0.5; k += 1.0) ticks.values.push_back(k * ticks.step);
  return ticks;
}

std::string format_tick(double value, double step) {
  if (std::abs(value) < 1e-9 * std::abs(step)) value = 0.0;  // no "-0"
  char buf[64];
  if (std::abs(value) >= 1e6 || (step > 0.0 && step < 1e-5)) {
    std::snprintf(buf, sizeof buf, "%.3g", value);
  } else {
    const int decimals = step > 0.0 ? std::max(0, static_cast<int>(-std::floor(std::log10(step) + 1e-9))) : 0;
    std::snprintf(buf, sizeof buf, "%.*f", decimals, value);
  }
  return buf;
}

}  // namespace facadeslam::plot
