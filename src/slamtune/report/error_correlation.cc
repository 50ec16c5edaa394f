// Objectives against ground-truth error (error_correlation.h).
#include "slamtune/report/error_correlation.h"

#include <fmt/format.h>

#include <set>

#include "slamtune/common/error.h"
#include "slamtune/optim/search_space.h"
#include "slamtune/report/report_text.h"

namespace slamtune::report {
namespace {

std::string Reading(const std::string& title, const RankCorrelation& s, const CorrelationReadingOptions& o) {
  if (!s.defined) return fmt::format("{}: no correlation ({}).", title, s.note);
  const std::string figures = fmt::format("rho = {:.2f}, n = {}", s.rho, s.n);
  if (s.n < o.min_sets) return fmt::format("{}: too few parameter sets to judge ({}).", title, figures);
  if (s.rho >= o.strong) return fmt::format("{} tracks the error: lower values went with lower error ({}).", title, figures);
  if (s.rho >= o.weak) return fmt::format("{} tracks the error only weakly ({}).", title, figures);
  if (s.rho > -o.weak) return fmt::format("{} does not track the error ({}).", title, figures);
  return fmt::format("{} runs against the error: lower values went with higher error ({}).", title, figures);
}

}  // namespace

void CorrelationReadingOptions::Validate() const {
  if (!(weak > 0.0 && weak < 1.0)) {
    throw InputError(fmt::format("CorrelationReadingOptions.weak = {}: must be in (0, 1)", weak));
  }
  if (!(strong > weak && strong <= 1.0)) {
    throw InputError(fmt::format("CorrelationReadingOptions.strong = {}: must be in (weak = {}, 1]", strong, weak));
  }
  if (min_sets < 3) throw InputError(fmt::format("CorrelationReadingOptions.min_sets = {}: must be >= 3", min_sets));
}

std::vector<optim::EvaluationRecord> GroundTruthRuns(const std::vector<optim::EvaluationRecord>& evaluations) {
  std::vector<optim::EvaluationRecord> out;
  std::set<std::string> seen;
  for (const auto& e : evaluations) {
    if (e.status != "ok" || !e.has_gt) continue;
    const std::string key = e.key.empty() ? optim::SearchSpace::Key(e.params) : e.key;
    if (seen.insert(key).second) out.push_back(e);
  }
  return out;
}

ErrorCorrelationSummary CorrelateObjectivesWithError(const std::vector<optim::EvaluationRecord>& evaluations,
                                                     const CorrelationReadingOptions& options) {
  options.Validate();
  const std::vector<optim::EvaluationRecord> runs = GroundTruthRuns(evaluations);
  ErrorCorrelationSummary out;
  out.parameter_sets = static_cast<int>(runs.size());
  std::vector<double> error;
  for (const auto& r : runs) error.push_back(r.trans_mean_m);
  std::string readings;
  for (std::size_t k = 0; k < kObjectives.size(); ++k) {
    std::vector<double> values;
    for (const auto& r : runs) values.push_back(ObjectiveValues(r)[k]);
    ObjectiveErrorCorrelation c;
    c.objective = kObjectives[k].key;
    c.spearman = SpearmanCorrelation(values, error);
    c.reading = Reading(kObjectives[k].title, c.spearman, options);
    readings += " " + c.reading;
    out.objectives.push_back(std::move(c));
  }
  out.statement = fmt::format(
      "Spearman rank correlation between each objective and the mean translational error, over the {} distinct "
      "parameter sets that ran with ground truth on this log.{} A high rho can come mostly from a few runs whose "
      "loop closure failed; check the scatter plot before reading it as a ranking of working runs.",
      out.parameter_sets, readings);
  return out;
}

}  // namespace slamtune::report
