// Axis ticks at "nice" numbers (1, 2 or 5 times a power of ten) for the report's plots.
//
// Follows Heckbert, "Nice numbers for graph labels", Graphics Gems (1990): the range is
// rounded to a nice number, the step to a nice number near range / (ticks - 1), and the axis
// is widened to whole steps so that both ends carry a tick ("loose" labelling). Degenerate
// ranges (empty, a single value, non-finite ends) are widened first, so every call gives at
// least two ticks and a positive step.
#pragma once

#include <string>
#include <vector>

namespace slamtune::report {

struct AxisTicks {
  double lower = 0.0;               // axis start (the first tick), <= the data minimum
  double upper = 1.0;               // axis end (the last tick), >= the data maximum
  double step = 0.5;                // distance between ticks, > 0
  std::vector<double> values;       // lower, lower + step, ..., upper
  std::vector<std::string> labels;  // one per value, formatted to the step's precision
};

// Heckbert's NiceNum: a nice number near `x` (> 0). With `round`, the nearest of 1, 2, 5, 10
// times a power of ten; otherwise the smallest such number >= x.
double NiceNumber(double x, bool round);

// Ticks covering [lo, hi] with about `target_count` ticks (>= 2). lo > hi is swapped;
// lo == hi is widened around the value; non-finite ends give the axis [0, 1].
AxisTicks MakeNiceTicks(double lo, double hi, int target_count);

// Ticks for an axis that spans exactly [lo, hi] (lo < hi, both finite): MakeNiceTicks's ticks
// that fall inside it, with lower = lo and upper = hi (the axis may end between ticks).
AxisTicks MakeTicksWithin(double lo, double hi, int target_count);

// Text of a tick value for a given step: enough decimals to tell neighbours apart, no
// trailing noise ("0.30000000000000004" -> "0.3"), "-0" printed as "0", and scientific
// notation for very large or very small magnitudes.
std::string FormatTick(double value, double step);

}  // namespace slamtune::report
