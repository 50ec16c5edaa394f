#include "slamtune/optim/equivalent_region.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>

namespace slamtune::optim {
namespace {

std::string ParameterValueText(double v, bool integer) {
  if (integer) return fmt::format("{:.0f}", v);
  return fmt::format("{:.4g}", v);
}

// The identity of a parameter set: its key, or its values when the key was not filled in.
std::string Identity(const EvaluationRecord& r) {
  if (!r.key.empty()) return r.key;
  std::string out;
  for (const auto& [name, value] : r.params) out += fmt::format("{}={:.17g};", name, value);
  return out;
}

}  // namespace

std::string EquivalentRegion::Describe() const {
  std::string out;
  for (const ParameterRange& r : ranges) {
    out += (out.empty() ? "" : ", ") + r.name;
    out += r.lower == r.upper
               ? " = " + ParameterValueText(r.lower, r.integer)
               : " in [" + ParameterValueText(r.lower, r.integer) + ", " + ParameterValueText(r.upper, r.integer) + "]";
  }
  if (out.empty()) out = "the recommended parameter set";
  return out + fmt::format(" give{} an equivalent map ({} of {} evaluated parameter set{})",
                           ranges.size() <= 1 ? "s" : "", members, evaluated, evaluated == 1 ? "" : "s");
}

std::optional<EquivalentRegion> FindEquivalentRegion(const std::vector<EvaluationRecord>& evaluations,
                                                     const EvaluationRecord& recommended, const SearchSpace& space,
                                                     const ObjectiveSet& objectives, double tolerance) {
  if (recommended.status != RunStatus::kOk) return std::nullopt;
  // Successful runs, once per parameter set.
  std::vector<const EvaluationRecord*> runs;
  std::set<std::string> seen;
  for (const EvaluationRecord& r : evaluations) {
    if (r.status == RunStatus::kOk && seen.insert(Identity(r)).second) runs.push_back(&r);
  }
  if (seen.insert(Identity(recommended)).second) runs.push_back(&recommended);

  const std::size_t m = objectives.size();
  std::vector<double> lower(m, std::numeric_limits<double>::infinity());
  std::vector<double> upper(m, -std::numeric_limits<double>::infinity());
  for (const EvaluationRecord* r : runs) {
    const std::vector<double> v = objectives.Values(*r);
    for (std::size_t k = 0; k < m; ++k) {
      lower[k] = std::min(lower[k], v[k]);
      upper[k] = std::max(upper[k], v[k]);
    }
  }
  const std::vector<double> target = objectives.Values(recommended);

  EquivalentRegion region;
  region.tolerance = tolerance;
  region.loop_closures = recommended.loop_closures;
  region.evaluated = runs.size();
  for (const Dimension& d : space.dimensions) {
    region.ranges.push_back(
        {d.name, std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity(), d.integer});
  }
  for (const EvaluationRecord* r : runs) {
    if (r->loop_closures != recommended.loop_closures) continue;
    const std::vector<double> v = objectives.Values(*r);
    bool close = true;
    for (std::size_t k = 0; k < m && close; ++k)
      close = std::abs(v[k] - target[k]) <= tolerance * (upper[k] - lower[k]);
    if (!close) continue;
    ++region.members;
    for (ParameterRange& range : region.ranges) {
      const auto it = r->params.find(range.name);
      if (it == r->params.end()) continue;
      range.lower = std::min(range.lower, it->second);
      range.upper = std::max(range.upper, it->second);
    }
  }
  // A parameter no member names (not in the records): drop it rather than print infinities.
  region.ranges.erase(std::remove_if(region.ranges.begin(), region.ranges.end(),
                                     [](const ParameterRange& r) { return r.lower > r.upper; }),
                      region.ranges.end());
  return region;
}

}  // namespace slamtune::optim
