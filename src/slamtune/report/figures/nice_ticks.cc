// Heckbert's loose labelling (nice_ticks.h).
#include "slamtune/report/figures/nice_ticks.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "slamtune/common/error.h"

namespace slamtune::report {

double NiceNumber(double x, bool round) {
  SLAMTUNE_CHECK(x > 0.0 && std::isfinite(x));
  const double exponent = std::floor(std::log10(x));
  const double power = std::pow(10.0, exponent);
  const double fraction = x / power;  // in [1, 10)
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

AxisTicks MakeNiceTicks(double lo, double hi, int target_count) {
  const int count = std::max(target_count, 2);
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    lo = 0.0;
    hi = 1.0;
  }
  if (lo > hi) std::swap(lo, hi);
  if (!std::isfinite(hi - lo)) {  // e.g. -DBL_MAX .. DBL_MAX: keep the range representable
    lo = std::max(lo, -1e307);
    hi = std::min(hi, 1e307);
  }
  if (hi - lo <= 1e-12 * std::max(std::abs(lo), std::abs(hi))) {
    // A single value: widen by 10 % of its magnitude (or +-0.5 around zero).
    const double half = lo == 0.0 ? 0.5 : 0.1 * std::abs(lo);
    lo -= half;
    hi += half;
  }
  // Heckbert 1990: nice range, then a nice step, then extend to whole steps.
  const double range = NiceNumber(hi - lo, false);
  const double step = NiceNumber(range / (count - 1), true);
  AxisTicks ticks;
  ticks.step = step;
  ticks.lower = std::floor(lo / step) * step;
  ticks.upper = std::ceil(hi / step) * step;
  const long n = std::lround((ticks.upper - ticks.lower) / step);
  for (long i = 0; i <= n; ++i) {
    const double v = ticks.lower + static_cast<double>(i) * step;
    ticks.values.push_back(v);
    ticks.labels.push_back(FormatTick(v, step));
  }
  return ticks;
}

AxisTicks MakeTicksWithin(double lo, double hi, int target_count) {
  AxisTicks ticks = MakeNiceTicks(lo, hi, target_count);
  ticks.lower = lo;
  ticks.upper = hi;
  std::vector<double> values;
  std::vector<std::string> labels;
  const double tolerance = 1e-9 * ticks.step;
  for (std::size_t i = 0; i < ticks.values.size(); ++i) {
    if (ticks.values[i] < lo - tolerance || ticks.values[i] > hi + tolerance) continue;
    values.push_back(ticks.values[i]);
    labels.push_back(ticks.labels[i]);
  }
  ticks.values = std::move(values);
  ticks.labels = std::move(labels);
  return ticks;
}

std::string FormatTick(double value, double step) {
  if (std::abs(value) < 1e-9 * std::abs(step)) value = 0.0;  // "-0" and rounding residue
  const double magnitude = std::max(std::abs(value), std::abs(step));
  if (magnitude >= 1e6 || (step < 1e-4 && magnitude < 1e-3)) {
    // Scientific: digits enough to separate neighbouring ticks.
    const int digits = std::clamp(static_cast<int>(std::ceil(std::log10(magnitude / step))) + 1, 1, 12);
    return fmt::format("{:.{}g}", value, digits);
  }
  const int decimals = std::clamp(-static_cast<int>(std::floor(std::log10(step) + 1e-9)), 0, 12);
  return fmt::format("{:.{}f}", value, decimals);
}

}  // namespace slamtune::report
