#pragma once
// Axis ticks at "nice" values (1, 2 or 5 times a power of ten), after
// Heckbert, "Nice numbers for graph labels" (Graphics Gems, 1990).
#include <string>
#include <vector>

namespace facadeslam::plot {

struct AxisTicks {
  double lo = 0.0;             // first tick, <= the data minimum
  double hi = 1.0;             // last tick, >= the data maximum
  double step = 0.2;           // distance between ticks
  std::vector<double> values;  // lo, lo + step, ..., hi
};

// About `target_count` ticks covering [lo, hi] (the ends may come in either
// order). An empty range is widened around its value. Throws Error on
// non-finite ends or target_count < 2.
AxisTicks nice_ticks(double lo, double hi, int target_count = 6);

// A tick value printed with as many decimals as the step needs ("0.2",
// "-10", "1e+08"); never "-0".
std::string format_tick(double value, double step);

}  // namespace facadeslam::plot
