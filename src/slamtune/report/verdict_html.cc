// report.html's verdict section (verdict_html.h).
#include "slamtune/report/verdict_html.h"

#include <fmt/format.h>

#include <optional>
#include <string>
#include <vector>

#include "slamtune/report/recommendation_assessment.h"
#include "slamtune/report/report_text.h"

namespace slamtune::report {

namespace {

// " (r=3 g=12)": a set in the text only when it is short (two or three parameters); the tables list it anyway.
std::string SetInParentheses(const optim::Candidate& c, const optim::SearchSpace& space) {
  const std::string summary = ParamSummary(c.record.params, space);
  return summary.size() <= 60 ? " (" + summary + ")" : "";
}

// Why the set was recommended: how far the final population agreed on it, and the knee beside it.
std::string WhyRecommended(const optim::OptimizeResult& r, const RecommendationAssessment& a) {
  const std::string params = SetInParentheses(*r.Find("recommended"), r.space);
  const std::string of = a.population > 0 ? fmt::format(" of {}", a.population) : "";
  std::string why;
  switch (a.agreement) {
    case Agreement::kNone:
      why = fmt::format(
          "The rule is the seed paper's: recommend the parameter set most individuals of the final population "
          "share. Here no set is shared by more than one individual{}, so there is no majority to go by: the "
          "recommendation{} falls back to the tie-break, the individual with the lowest sum of objectives "
          "normalised over the population. The population had not converged.",
          of, params);
      break;
    case Agreement::kMajority:
      why = fmt::format(
          "{}{} individuals of the final population hold the recommended set{}: the search "
          "converged on it, as the seed paper's rule (the set most individuals share) asks.",
          a.share, of, params);
      break;
    case Agreement::kPlurality:
      why = fmt::format(
          "The recommended set{} is the one most individuals of the final population share, but only {}{} hold "
          "it: the largest group, not a majority, so the search had not settled and the choice is tentative.",
          params, a.share, of);
      break;
  }
  switch (a.knee) {
    case KneeRelation::kNoKnee: break;
    case KneeRelation::kSameSet:
      why +=
          " It is also the knee of the final front (the front's member closest to the ideal point), so "
          "both rules agree.";
      break;
    case KneeRelation::kOtherSet:
      why += " The knee of the final front is another set" + SetInParentheses(*r.Find("knee"), r.space) +
             ": compare the two maps below.";
      break;
  }
  return why;
}

std::string BoundWarning(const BoundHit& hit) {
  const std::string symbol = ShortParamName(hit.name);
  return fmt::format(
      "{} = {} sits on the {} bound of its search range [{}, {}]{}: the best value may lie beyond it. Widen the "
      "range on that side (--vary {}=MIN:MAX, or the min and max under vary: in a --space file) and run again "
      "before trusting this value.",
      symbol, FormatParam(hit.value), hit.at_lower ? "lower" : "upper", FormatParam(hit.lower), FormatParam(hit.upper),
      symbol == hit.name ? "" : " (" + hit.name + ")", hit.name);
}

std::string NextStepText(NextStep step, const std::string& base_label) {
  switch (step) {
    case NextStep::kLoadAndConfirm:
      return "Load the recommended parameters (best.yaml, or best_slam_karto.yaml for slam_karto) as shown "
             "below, and map a log the tuning did not see to confirm.";
    case NextStep::kReadWhyItFailed:
      return "Read why the run failed (status column of the candidates) before changing anything.";
    case NextStep::kKeepBase:
      return "Keep " + (base_label.empty() ? std::string("the base configuration") : base_label) +
             ": the recommendation does not map this log clearly better.";
    case NextStep::kWidenRange: return "Widen the search range where a value sits on a bound (above).";
    case NextStep::kRunLonger:
      return "Run again with more generations (--generations) or a larger population (--population) so "
             "the population converges on one set.";
    case NextStep::kCheckLoopClosures:
      return "Check the maps: each vermillion line is a loop closure between two scan poses, and the scans at "
             "its two ends must see the same walls; a closure between places that only look alike (a twin "
             "corridor, the far side of a wall) is a false loop closure.";
    case NextStep::kAddGroundTruth:
      return "With ground truth for this log (--relations FILE), the report also ranks the candidates by "
             "their true trajectory error.";
  }
  return "";
}

// How sure: the evaluated sets that gave the recommendation's map (optim/equivalent_region.h).
void EquivalentRegionSection(HtmlPage& page, const optim::OptimizeResult& r) {
  if (!r.equivalent_region) return;
  const optim::EquivalentRegion& e = *r.equivalent_region;
  page.Heading(3, "How sure: the parameter sets with an equivalent map", "equivalent");
  page.Paragraph(e.Describe() + ".");
  page.Paragraph(
      fmt::format("Equivalent: the run closed as many loops as the recommendation ({}), and each objective "
                  "differs from the recommendation's by at most {:.0f} % of that objective's range over all "
                  "successful evaluations. The ranges are the smallest box around those parameter sets; sets "
                  "inside it that were not evaluated are not known. {}",
                  e.loop_closures, 100.0 * e.tolerance,
                  e.members <= 1 ? "Only the recommendation itself qualifies: the result is sensitive to its "
                                   "exact values, or the search sampled little around it."
                                 : "A wide range says the value is not critical there; a narrow one says it is."),
      "note");
}

}  // namespace

// Why this set was recommended (with any warning), then what to do and how.
void VerdictSection(HtmlPage& page, const optim::OptimizeResult& r) {
  page.Heading(2, "Verdict");
  // Scans of the recording no run maps: the verdict holds for the rest only.
  for (const std::string& line : r.source.scans_not_used.LossLines()) {
    const std::string what = "Not used" + line.substr(line.find(':'));
    page.Paragraph(what + ". Every map and the recommendation are made without them.", "warning");
  }
  const std::optional<RecommendationAssessment> assessment = AssessRecommendation(r);
  if (assessment) {
    page.Heading(3, "Why this recommendation");
    page.Paragraph(WhyRecommended(r, *assessment));
    for (const BoundHit& hit : assessment->bound_hits) page.Paragraph(BoundWarning(hit), "warning");
    EquivalentRegionSection(page, r);
  }
  if (!r.lowest_error_label.empty()) {
    page.Paragraph("Against the ground-truth relations, the candidate with the lowest mean translational error is \"" +
                   r.lowest_error_label + "\".");
  }
  if (assessment) {
    page.Heading(3, "What to do next");
    std::vector<std::string> steps;
    for (NextStep step : assessment->next_steps) steps.push_back(NextStepText(step, r.base_label));
    page.List(steps);
  }
  if (!r.how_to_load.empty()) {
    page.Paragraph(r.changes.empty() ? "Keep " + r.base_label + ": the parameter files repeat it unchanged."
                                     : "Changes from " + r.base_label + ":");
    if (!r.changes.empty()) page.List(r.changes);
    page.Paragraph("To run it on the robot:");
    page.List(r.how_to_load);
  }
}

}  // namespace slamtune::report
