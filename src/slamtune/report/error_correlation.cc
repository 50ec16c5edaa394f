// Objectives against ground-truth error (error_correlation.h).
#include "slamtune/report/error_correlation.h"

#include <fmt/format.h>

#include <cctype>
#include <set>

#include "slamtune/common/error.h"
#include "slamtune/optim/search_space.h"
#include "slamtune/report/report_text.h"

namespace slamtune::report {
namespace {

Tracking Classify(const RankCorrelation& s, const CorrelationReadingOptions& o) {
  if (!s.defined || s.n < o.min_sets) return Tracking::kUndecided;
  if (s.rho >= o.strong) return Tracking::kTracks;
  if (s.rho >= o.weak) return Tracking::kWeakly;
  if (s.rho > -o.weak) return Tracking::kNot;
  return Tracking::kAgainst;
}

std::string Capitalised(std::string text) {
  if (!text.empty()) text[0] = static_cast<char>(std::toupper(static_cast<unsigned char>(text[0])));
  return text;
}

std::string Reading(const std::string& title, const RankCorrelation& s, Tracking t) {
  const std::string figures = fmt::format("rho = {:.2f}, n = {}", s.rho, s.n);
  switch (t) {
    case Tracking::kTracks:
      return Capitalised(fmt::format("{} tracks the error: lower values went with lower error ({}).", title, figures));
    case Tracking::kWeakly: return Capitalised(fmt::format("{} tracks the error only weakly ({}).", title, figures));
    case Tracking::kNot: return Capitalised(fmt::format("{} does not track the error ({}).", title, figures));
    case Tracking::kAgainst:
      return Capitalised(
          fmt::format("{} runs against the error: lower values went with higher error ({}).", title, figures));
    case Tracking::kUndecided: break;
  }
  if (!s.defined) return Capitalised(fmt::format("{}: no correlation ({}).", title, s.note));
  return Capitalised(fmt::format("{}: too few parameter sets to judge ({}).", title, figures));
}

// "a", "a and b", "a, b and c".
std::string JoinNames(const std::vector<std::string>& names) {
  std::string out;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) out += i + 1 == names.size() ? " and " : ", ";
    out += names[i];
  }
  return out;
}

std::string Evidence(const std::vector<ObjectiveErrorCorrelation>& objectives) {
  const std::vector<std::pair<Tracking, std::string>> groups = {
      {Tracking::kTracks, "track{} the translational error"},
      {Tracking::kWeakly, "track{} it only weakly"},
      {Tracking::kNot, "do{} not track it"},
      {Tracking::kAgainst, "run{} against it (lower values, higher error)"},
      {Tracking::kUndecided, "cannot be judged from these runs"},
  };
  std::vector<std::string> parts;
  for (const auto& [tracking, phrase] : groups) {
    std::vector<std::string> names;
    for (std::size_t k = 0; k < objectives.size(); ++k) {
      if (objectives[k].tracking == tracking) names.push_back(objectives[k].short_name);
    }
    if (names.empty()) continue;
    // Verb agreement: "eta tracks", "eta and n_c track"; "does"/"do"; "runs"/"run".
    const bool one = names.size() == 1;
    std::string verb = fmt::format(fmt::runtime(phrase), one ? (tracking == Tracking::kNot ? "es" : "s") : "");
    parts.push_back(JoinNames(names) + " " + verb);
  }
  return "On this log, " + JoinNames(parts) + ".";
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
    if (e.status != optim::RunStatus::kOk || !e.has_gt) continue;
    const std::string key = e.key.empty() ? optim::SearchSpace::Key(e.params) : e.key;
    if (seen.insert(key).second) out.push_back(e);
  }
  return out;
}

ErrorCorrelationSummary CorrelateObjectivesWithError(const std::vector<optim::EvaluationRecord>& evaluations,
                                                     const std::vector<optim::Objective>& objectives,
                                                     const CorrelationReadingOptions& options) {
  options.Validate();
  const std::vector<optim::EvaluationRecord> runs = GroundTruthRuns(evaluations);
  ErrorCorrelationSummary out;
  out.parameter_sets = static_cast<int>(runs.size());
  std::vector<double> error;
  for (const auto& r : runs) error.push_back(r.trans_mean_m);
  for (optim::Objective objective : objectives) {
    const optim::RecordFigure& info = optim::InfoOf(objective);
    std::vector<double> values;
    for (const auto& r : runs) values.push_back(optim::ValueOf(r, objective));
    ObjectiveErrorCorrelation c;
    c.objective = info.key;
    c.short_name = info.short_name;
    c.spearman = SpearmanCorrelation(values, error);
    c.tracking = Classify(c.spearman, options);
    c.reading = Reading(info.title, c.spearman, c.tracking);
    out.objectives.push_back(std::move(c));
  }
  out.statement = fmt::format(
      "{} (Spearman rank correlation of each objective with the mean translational error over the {} distinct "
      "parameter sets that ran with ground truth; positive rho: lower objective, lower error.) A high rho can come "
      "mostly from a few runs whose loop closure failed; check the scatter plot before reading it as a ranking of "
      "working runs.",
      Evidence(out.objectives), out.parameter_sets);
  return out;
}

}  // namespace slamtune::report
