// The judgements on a run's recommendation (recommendation_assessment.h).
#include "slamtune/report/recommendation_assessment.h"

#include "slamtune/report/report_text.h"

namespace slamtune::report {

namespace {

Agreement AgreementOf(int share, std::size_t population) {
  if (share <= 1) return Agreement::kNone;
  // Without the population's size, two individuals holding the set count as agreement.
  const bool majority = population == 0 || 2 * static_cast<std::size_t>(share) > population;
  return majority ? Agreement::kMajority : Agreement::kPlurality;
}

KneeRelation KneeRelationOf(const optim::Candidate& recommended, const optim::Candidate* knee) {
  if (knee == nullptr || knee == &recommended) return KneeRelation::kNoKnee;
  const optim::EvaluationRecord &rec = recommended.record, &k = knee->record;
  const bool same = !rec.key.empty() ? rec.key == k.key : rec.params == k.params;
  return same ? KneeRelation::kSameSet : KneeRelation::kOtherSet;
}

// The recommended values on a bound of their range; a dimension without a range (upper <= lower)
// or without a recommended value has none.
std::vector<BoundHit> BoundHitsOf(const optim::EvaluationRecord& recommended, const optim::SearchSpace& space) {
  std::vector<BoundHit> hits;
  for (const optim::Dimension& d : space.dimensions) {
    const auto it = recommended.params.find(d.name);
    if (it == recommended.params.end() || !(d.upper > d.lower)) continue;
    const double v = it->second;
    const double tolerance = d.integer ? 0.0 : 0.01 * (d.upper - d.lower);
    const bool low = v <= d.lower + tolerance, high = v >= d.upper - tolerance;
    if (low || high) hits.push_back({d.name, v, d.lower, d.upper, low});
  }
  return hits;
}

std::vector<NextStep> NextStepsOf(const RecommendationAssessment& a, optim::VerdictKind verdict, bool ground_truth) {
  std::vector<NextStep> steps;
  switch (verdict) {
    case optim::VerdictKind::kBetter: steps.push_back(NextStep::kLoadAndConfirm); break;
    case optim::VerdictKind::kFailed: steps.push_back(NextStep::kReadWhyItFailed); break;
    default: steps.push_back(NextStep::kKeepBase); break;
  }
  if (!a.bound_hits.empty()) steps.push_back(NextStep::kWidenRange);
  if (!a.converged()) steps.push_back(NextStep::kRunLonger);
  steps.push_back(NextStep::kCheckLoopClosures);
  if (!ground_truth) steps.push_back(NextStep::kAddGroundTruth);
  return steps;
}

}  // namespace

std::optional<RecommendationAssessment> AssessRecommendation(const optim::OptimizeResult& result) {
  const optim::Candidate* recommended = result.Find("recommended");
  if (recommended == nullptr) return std::nullopt;
  RecommendationAssessment a;
  a.share = result.recommended_share;
  a.population = result.population;
  a.agreement = AgreementOf(a.share, a.population);
  a.knee = KneeRelationOf(*recommended, result.Find("knee"));
  a.bound_hits = BoundHitsOf(recommended->record, result.space);
  a.next_steps = NextStepsOf(a, result.verdict_kind, HasGroundTruth(result));
  return a;
}

}  // namespace slamtune::report
