// What a finished optimisation says about its recommendation, as values: how far the final
// population agreed on the recommended set (the seed paper's rule recommends the set most
// individuals share), whether the knee of the final front is the same set, which recommended
// values sit on a bound of their search range, and the next steps those findings, the verdict
// and the ground truth call for. report.html states them in words (verdict_html.h); this file
// decides them, from the typed result alone (optim/optimize_result.h).
//
// In report/ rather than optim/: it needs only optim's types and report's HasGroundTruth
// (report_text.h), and it is advice to the reader of the report, not a step of the search.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/optim/optimize_result.h"

namespace slamtune::report {

// How far the final population agreed on the recommended set.
enum class Agreement {
  kNone,       // no set is held by more than one individual: the tie-break chose
  kPlurality,  // the largest group, but not a majority: the search had not settled
  kMajority,   // more than half the population (population unknown: more than one individual)
};

// How the knee of the final front relates to the recommended set.
enum class KneeRelation {
  kNoKnee,    // the result has no knee candidate
  kSameSet,   // the same parameter set (EvaluationRecord::key, or the parameters when a key is empty)
  kOtherSet,  // another set
};

// A recommended value on a bound of its search range: an integer on the bound itself, a real
// within 1 % of the range from it. The best value may lie beyond the bound.
struct BoundHit {
  std::string name;  // the parameter's ROS name
  double value = 0.0;
  double lower = 0.0, upper = 0.0;  // its search range
  bool at_lower = false;            // the lower bound (else the upper one)
};

// What to do next, in the order the report lists them.
enum class NextStep {
  kLoadAndConfirm,     // the verdict is better: load the recommended files, map an unseen log
  kReadWhyItFailed,    // the verdict is failed: read the candidates' status before changing anything
  kKeepBase,           // otherwise: keep the base configuration
  kWidenRange,         // a recommended value sits on a bound
  kRunLonger,          // the population did not converge: more generations or a larger population
  kCheckLoopClosures,  // always: look for false loop closures on the maps
  kAddGroundTruth,     // no ground truth: --relations would rank the candidates by true error
};

struct RecommendationAssessment {
  int share = 0;               // individuals of the final population that hold the recommended set
  std::size_t population = 0;  // individuals of the final population; 0 when not known
  Agreement agreement = Agreement::kNone;
  KneeRelation knee = KneeRelation::kNoKnee;
  std::vector<BoundHit> bound_hits;  // in the order of the space's dimensions
  std::vector<NextStep> next_steps;

  // The search converged on the recommendation: a majority holds it.
  bool converged() const { return agreement == Agreement::kMajority; }
};

// The assessment of `result`'s "recommended" candidate; nullopt when it has none.
std::optional<RecommendationAssessment> AssessRecommendation(const optim::OptimizeResult& result);

}  // namespace slamtune::report
