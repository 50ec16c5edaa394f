#include "slamtune/optim/candidate_selection.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "slamtune/common/error.h"

namespace slamtune::optim {
namespace {

// Per vector, the sum over objectives of (f - min) / (max - min), min and max over the vectors
// `counted` marks (all when it is empty or marks none; zero ranges count 0). `scores` must not
// be empty and its vectors must have one length.
std::vector<double> NormalisedSums(const std::vector<std::vector<double>>& scores,
                                   const std::vector<bool>& counted = {}) {
  const std::size_t m = scores.front().size();
  const bool all = std::find(counted.begin(), counted.end(), true) == counted.end();
  std::vector<double> lo(m, std::numeric_limits<double>::infinity()), hi(m, -lo[0]);
  for (std::size_t i = 0; i < scores.size(); ++i) {
    const auto& f = scores[i];
    SLAMTUNE_CHECK(f.size() == m);
    if (!all && !counted[i]) continue;
    for (std::size_t k = 0; k < m; ++k) {
      lo[k] = std::min(lo[k], f[k]);
      hi[k] = std::max(hi[k], f[k]);
    }
  }
  std::vector<double> sums(scores.size(), 0.0);
  for (std::size_t i = 0; i < scores.size(); ++i)
    for (std::size_t k = 0; k < m; ++k) sums[i] += hi[k] > lo[k] ? (scores[i][k] - lo[k]) / (hi[k] - lo[k]) : 0.0;
  return sums;
}

// The same over the records `among` (non-empty), indexed like `records` (others 0).
std::vector<double> NormalisedSums(const std::vector<EvaluationRecord>& records, const std::vector<std::size_t>& among,
                                   const ObjectiveSet& objectives) {
  std::vector<std::vector<double>> scores;
  for (std::size_t i : among) scores.push_back(objectives.Score(records[i]));
  const std::vector<double> among_sums = NormalisedSums(scores);
  std::vector<double> sums(records.size(), 0.0);
  for (std::size_t j = 0; j < among.size(); ++j) sums[among[j]] = among_sums[j];
  return sums;
}

std::vector<std::size_t> OkIndices(const std::vector<EvaluationRecord>& records) {
  std::vector<std::size_t> ok;
  for (std::size_t i = 0; i < records.size(); ++i)
    if (records[i].status == RunStatus::kOk) ok.push_back(i);
  return ok;
}

}  // namespace

std::size_t MajorityIndex(const std::vector<std::string>& keys, const std::vector<std::vector<double>>& scores,
                          const std::vector<bool>& ok) {
  SLAMTUNE_CHECK(!keys.empty() && keys.size() == scores.size() && keys.size() == ok.size());
  std::map<std::string, int> count;
  for (const auto& key : keys) ++count[key];
  // Ranges over the runs that did not fail: a failed run's score (worse than any map, e.g. 1e9
  // corner pixels) would squash one objective's range and leave the others to decide alone.
  const std::vector<double> sums = NormalisedSums(scores, ok);
  std::size_t best = 0;
  for (std::size_t i = 1; i < keys.size(); ++i) {
    const int c = count[keys[i]], best_c = count[keys[best]];
    if ((ok[i] && !ok[best]) || (ok[i] == ok[best] && (c > best_c || (c == best_c && sums[i] < sums[best])))) best = i;
  }
  return best;
}

Recommendation RecommendByMajority(const std::vector<EvaluationRecord>& population, const ObjectiveSet& objectives) {
  SLAMTUNE_CHECK(!population.empty());
  std::vector<std::string> keys;
  std::vector<std::vector<double>> scores;
  std::vector<bool> ok;
  for (const auto& r : population) {
    keys.push_back(r.key);
    scores.push_back(objectives.Score(r));
    ok.push_back(r.status == RunStatus::kOk);
  }
  const std::size_t index = MajorityIndex(keys, scores, ok);
  return {index, static_cast<int>(std::count(keys.begin(), keys.end(), keys[index]))};
}

bool Dominates(const std::vector<double>& a, const std::vector<double>& b) {
  bool strictly = false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (a[k] > b[k]) return false;
    if (a[k] < b[k]) strictly = true;
  }
  return strictly;
}

std::vector<std::size_t> NonDominatedIndices(const std::vector<std::vector<double>>& f) {
  std::vector<std::size_t> front;
  for (std::size_t i = 0; i < f.size(); ++i) {
    bool dominated = false;
    for (std::size_t j = 0; j < f.size() && !dominated; ++j) dominated = j != i && Dominates(f[j], f[i]);
    if (!dominated) front.push_back(i);
  }
  return front;
}

std::size_t KneeIndex(const std::vector<std::vector<double>>& f) {
  const auto front = NonDominatedIndices(f);
  SLAMTUNE_CHECK(!front.empty());
  const std::size_t m = f[front.front()].size();
  std::vector<double> lo(m, std::numeric_limits<double>::infinity()), hi(m, -lo[0]);
  for (std::size_t i : front) {
    for (std::size_t k = 0; k < m; ++k) {
      lo[k] = std::min(lo[k], f[i][k]);
      hi[k] = std::max(hi[k], f[i][k]);
    }
  }
  std::size_t best = front.front();
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t i : front) {
    double d = 0.0;
    for (std::size_t k = 0; k < m; ++k) {
      const double z = hi[k] > lo[k] ? (f[i][k] - lo[k]) / (hi[k] - lo[k]) : 0.0;
      d += z * z;
    }
    if (d < best_d) {
      best_d = d;
      best = i;
    }
  }
  return best;
}

std::vector<std::size_t> NonDominated(const std::vector<EvaluationRecord>& records, const ObjectiveSet& objectives) {
  const auto ok = OkIndices(records);
  std::vector<std::vector<double>> scores;
  for (std::size_t i : ok) scores.push_back(objectives.Score(records[i]));
  std::vector<std::size_t> front;
  for (std::size_t k : NonDominatedIndices(scores)) front.push_back(ok[k]);
  return front;
}

std::size_t Knee(const std::vector<EvaluationRecord>& records, const ObjectiveSet& objectives) {
  const auto ok = OkIndices(records);
  SLAMTUNE_CHECK(!ok.empty());
  std::vector<std::vector<double>> scores;
  for (std::size_t i : ok) scores.push_back(objectives.Score(records[i]));
  return ok[KneeIndex(scores)];
}

std::size_t Worst(const std::vector<EvaluationRecord>& records, const ObjectiveSet& objectives) {
  SLAMTUNE_CHECK(!records.empty());
  const auto ok = OkIndices(records);
  if (ok.empty()) return 0;
  const auto sums = NormalisedSums(records, ok, objectives);
  std::size_t worst = ok.front();
  for (std::size_t i : ok)
    if (sums[i] > sums[worst]) worst = i;
  return worst;
}

const char* VerdictKindName(VerdictKind kind) {
  switch (kind) {
    case VerdictKind::kBetter: return "better";
    case VerdictKind::kEquivalent: return "equivalent";
    case VerdictKind::kWorse: return "worse";
    case VerdictKind::kMixed: return "mixed";
    case VerdictKind::kFailed: return "failed";
  }
  return "failed";
}

VerdictSummary Verdict(const EvaluationRecord& rec, const EvaluationRecord& base, const VerdictOptions& options) {
  const std::string& label = options.base_label;
  if (rec.status != RunStatus::kOk) {
    return {VerdictKind::kFailed, "The recommended parameter set failed to evaluate: " + rec.reason};
  }
  if (base.status != RunStatus::kOk) {
    return {VerdictKind::kFailed, fmt::format("{} failed to evaluate on this log: {}", label, base.reason)};
  }
  const auto a = options.objectives.Score(rec), b = options.objectives.Score(base);
  int better = 0, worse = 0;
  std::string detail;
  for (std::size_t k = 0; k < a.size(); ++k) {
    const double scale = std::max({std::fabs(a[k]), std::fabs(b[k]), 1e-12});
    const double rel = (a[k] - b[k]) / scale;
    if (rel < -options.equivalence_tolerance) ++better;
    if (rel > options.equivalence_tolerance) ++worse;
    detail += fmt::format("{}{} {:.4g} vs {:.4g}", k ? ", " : "", InfoOf(options.objectives.objectives()[k]).title,
                          a[k], b[k]);
  }
  const std::string loops =
      fmt::format("loop closures {} (recommended) vs {} (base)", rec.loop_closures, base.loop_closures);
  if (better == 0 && worse == 0) {
    return {VerdictKind::kEquivalent,
            fmt::format("Equivalent: the recommendation and {} give maps whose objectives differ by less than {:.0f}% "
                        "({}; {}). The objectives do not rank working runs this close; keep {} unless ground truth "
                        "says otherwise.",
                        label, 100 * options.equivalence_tolerance, detail, loops, label)};
  }
  if (worse == 0) {
    return {VerdictKind::kBetter,
            fmt::format("The recommendation gives a cleaner map than {} ({}; {}).", label, detail, loops)};
  }
  if (better == 0) {
    return {VerdictKind::kWorse, fmt::format("{} score{} better than the recommendation on this log ({}; {}).", label,
                                             label.ends_with("defaults") ? "" : "s", detail, loops)};
  }
  return {VerdictKind::kMixed,
          fmt::format("Mixed: the recommendation is better on some objectives and worse on others ({}; {}).", detail,
                      loops)};
}

}  // namespace slamtune::optim
