// How `slamtune optimize` picks the parameter sets it reports (issue: choosing the answer).
//
// * Recommended: the seed paper's choice (Han et al. 2020, §4.3) — the parameter set shared by
//   most individuals of the final population; ties go to the one with the lowest sum of
//   normalised objectives, then to the earliest.
// * Knee: the member of the final non-dominated front closest to the ideal point once each
//   objective is normalised by the front's range (a simple, scale-free knee).
// * Worst: the evaluated set with the largest sum of normalised objectives (the paper shows it
//   for contrast).
// * Verdict: compares the recommendation with the base configuration in plain words. The
//   objectives separate failed loop closure from working runs well but barely rank working
//   runs, so differences within `equivalence_tolerance` are called equivalent, not a gain.
#pragma once

#include <string>
#include <vector>

#include "slamtune/optim/evaluation_record.h"
#include "slamtune/optim/objective_set.h"

namespace slamtune::optim {

struct Recommendation {
  std::size_t index = 0;  // into the population
  int share = 0;          // individuals with the same parameter set
};

// The recommendation on objective vectors, shared with the settling rule: index of the individual
// whose parameter set (`keys[i]`) most individuals share, preferring runs that did not fail
// (`ok[i]`); ties go to the lowest sum of objectives normalised over the individuals that did not
// fail (min-max per objective, zero ranges count 0; over all when every one failed), then to the
// earliest. All three vectors have one entry per
// individual and must not be empty.
std::size_t MajorityIndex(const std::vector<std::string>& keys, const std::vector<std::vector<double>>& scores,
                          const std::vector<bool>& ok);

// Pareto helpers on objective vectors (all minimised), shared with the settling rule.
bool Dominates(const std::vector<double>& a, const std::vector<double>& b);
// Indices of the non-dominated vectors of `f`, in input order.
std::vector<std::size_t> NonDominatedIndices(const std::vector<std::vector<double>>& f);
// Index into `f` of the non-dominated vector closest to the ideal point once each objective is
// normalised by the front's range. `f` must not be empty.
std::size_t KneeIndex(const std::vector<std::vector<double>>& f);

// Every function below ranks records by `objectives` (objective_set.h).

// `population`: the final population's records (one per individual). Must not be empty.
Recommendation RecommendByMajority(const std::vector<EvaluationRecord>& population, const ObjectiveSet& objectives);

// Indices of the non-dominated records (status ok) of `records`, in input order.
std::vector<std::size_t> NonDominated(const std::vector<EvaluationRecord>& records, const ObjectiveSet& objectives);

// Index of the knee of `records`' non-dominated front. Must contain an ok record.
std::size_t Knee(const std::vector<EvaluationRecord>& records, const ObjectiveSet& objectives);

// Index of the worst ok record (largest sum of objectives normalised over all ok records);
// a failed record only when none is ok.
std::size_t Worst(const std::vector<EvaluationRecord>& records, const ObjectiveSet& objectives);

struct VerdictOptions {
  ObjectiveSet objectives;                           // what is compared
  double equivalence_tolerance = 0.05;               // relative difference per objective treated as no difference
  std::string base_label = "slam_karto's defaults";  // what the recommendation is compared with
};

enum class VerdictKind { kBetter, kEquivalent, kWorse, kMixed, kFailed };
// "better", "equivalent", "worse", "mixed", "failed".
const char* VerdictKindName(VerdictKind kind);

struct VerdictSummary {
  VerdictKind kind = VerdictKind::kFailed;
  std::string text;  // one paragraph
  bool better() const { return kind == VerdictKind::kBetter; }
};

// Compares `recommended` with `base` (the configuration tuned from).
VerdictSummary Verdict(const EvaluationRecord& recommended, const EvaluationRecord& base,
                       const VerdictOptions& options = {});

}  // namespace slamtune::optim
