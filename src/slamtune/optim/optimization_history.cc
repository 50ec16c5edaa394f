#include "slamtune/optim/optimization_history.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <pagmo/utils/hypervolume.hpp>

#include "slamtune/optim/candidate_selection.h"

namespace slamtune::optim {

double Hypervolume(const std::vector<std::vector<double>>& points, double reference) {
  std::vector<std::vector<double>> inside;
  for (const auto& p : points) {
    if (!p.empty() && std::all_of(p.begin(), p.end(), [&](double v) { return std::isfinite(v) && v < reference; })) {
      inside.push_back(p);
    }
  }
  if (inside.empty()) return 0.0;
  const std::size_t m = inside.front().size();
  if (m == 1) {
    double best = reference;
    for (const auto& p : inside) best = std::min(best, p[0]);
    return reference - best;
  }
  const pagmo::hypervolume hv(inside, true);
  return hv.compute(pagmo::vector_double(m, reference));
}

OptimizationHistory SummarizeGenerations(const std::vector<std::vector<std::vector<double>>>& populations,
                                         const ObjectiveSet& objectives) {
  const std::size_t m = objectives.size();
  OptimizationHistory out;
  out.lower.assign(m, std::numeric_limits<double>::infinity());
  out.upper.assign(m, -std::numeric_limits<double>::infinity());
  auto ok = [&](const std::vector<double>& f) { return f.size() == m && !objectives.IsFailureScore(f); };
  for (const auto& population : populations) {
    for (const auto& f : population) {
      if (!ok(f)) continue;
      for (std::size_t k = 0; k < m; ++k) {
        out.lower[k] = std::min(out.lower[k], f[k]);
        out.upper[k] = std::max(out.upper[k], f[k]);
      }
    }
  }
  for (std::size_t g = 0; g < populations.size(); ++g) {
    GenerationSummary s;
    s.generation = static_cast<int>(g);
    s.best.assign(m, std::numeric_limits<double>::quiet_NaN());
    std::vector<std::vector<double>> normalised;
    for (const auto& f : populations[g]) {
      if (!ok(f)) {
        ++s.failed;
        continue;
      }
      std::vector<double> n(m);
      for (std::size_t k = 0; k < m; ++k) {
        s.best[k] = std::isnan(s.best[k]) ? f[k] : std::min(s.best[k], f[k]);
        const double span = out.upper[k] - out.lower[k];
        n[k] = span > 0.0 ? (f[k] - out.lower[k]) / span : 0.0;  // one value over all runs: every run at 0
      }
      normalised.push_back(std::move(n));
    }
    for (std::size_t i = 0; i < normalised.size(); ++i) {
      bool dominated = false;
      for (std::size_t j = 0; j < normalised.size() && !dominated; ++j)
        dominated = Dominates(normalised[j], normalised[i]);
      if (!dominated) ++s.front_size;
    }
    s.hypervolume = Hypervolume(normalised, kHypervolumeReference);
    out.generations.push_back(std::move(s));
  }
  if (out.generations.empty() || std::isinf(out.lower.empty() ? 0.0 : out.lower[0])) {
    // No successful run anywhere: no range to report.
    std::fill(out.lower.begin(), out.lower.end(), std::numeric_limits<double>::quiet_NaN());
    std::fill(out.upper.begin(), out.upper.end(), std::numeric_limits<double>::quiet_NaN());
  }
  return out;
}

}  // namespace slamtune::optim
