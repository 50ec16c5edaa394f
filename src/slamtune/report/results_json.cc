// results.json (results_json.h).
#include "slamtune/report/results_json.h"

#include <cmath>

#include "slamtune/report/front_end_json.h"
#include "slamtune/report/json_number.h"
#include "slamtune/report/scan_losses_json.h"

namespace slamtune::report {

nlohmann::json CandidateJson(const optim::Candidate& candidate) {
  const optim::EvaluationRecord& r = candidate.record;
  nlohmann::json j = r;  // the record's own JSON (optim/evaluation_record.h), then the report's fields
  j.erase("key");
  // The derived figures (not stored in the run database) beside the measured ones.
  if (r.status == optim::RunStatus::kOk) {
    for (const optim::RecordFigure& figure : optim::RecordFigures()) {
      if (figure.derived()) j["figures"][figure.key] = optim::FigureValue(figure, r);
    }
  }
  j["label"] = candidate.label;
  j["description"] = candidate.description;
  return j;
}

nlohmann::json SearchSpaceJson(const optim::SearchSpace& space) {
  nlohmann::json dims = nlohmann::json::array();
  for (const auto& d : space.dimensions) {
    dims.push_back({{"name", d.name}, {"lower", d.lower}, {"upper", d.upper}, {"type", d.integer ? "int" : "real"}});
  }
  return {{"dimensions", dims}, {"fixed", space.fixed}};
}

namespace {

// Per generation: the best value of each objective and the normalised front's hypervolume,
// with the ranges it was normalised by.
nlohmann::json HistoryJson(const optim::OptimizeResult& result) {
  const auto& objectives = result.objectives.objectives();
  const optim::OptimizationHistory& h = result.history;
  nlohmann::json ranges = nlohmann::json::object();
  for (std::size_t k = 0; k < objectives.size() && k < h.lower.size(); ++k) {
    ranges[optim::InfoOf(objectives[k]).key] = {FiniteOrNull(h.lower[k]), FiniteOrNull(h.upper[k])};
  }
  nlohmann::json generations = nlohmann::json::array();
  for (const optim::GenerationSummary& g : h.generations) {
    nlohmann::json best = nlohmann::json::object();
    for (std::size_t k = 0; k < objectives.size() && k < g.best.size(); ++k) {
      best[optim::InfoOf(objectives[k]).key] = FiniteOrNull(g.best[k]);
    }
    generations.push_back({{"generation", g.generation},
                           {"best", best},
                           {"hypervolume", g.hypervolume},
                           {"front_size", g.front_size},
                           {"failed", g.failed}});
  }
  return {{"reference", optim::kHypervolumeReference}, {"normalised_by", ranges}, {"generations", generations}};
}

}  // namespace

nlohmann::json ResultsJson(const optim::OptimizeResult& result,
                           const std::optional<ErrorCorrelationSummary>& correlation) {
  nlohmann::json j;
  for (const char* label : {"recommended", "knee", "worst", "default"}) {
    const optim::Candidate* c = result.Find(label);
    j[label] = c ? CandidateJson(*c) : nlohmann::json(nullptr);
  }
  nlohmann::json minimised = nlohmann::json::array();
  for (optim::Objective o : result.objectives.objectives()) minimised.push_back(optim::InfoOf(o).key);
  j["objectives"] = {{"set", result.objectives.name()}, {"minimised", minimised}};
  j["evaluations"] = result.evaluation_count;
  j["generations_run"] = result.generations_run;
  j["settling"] = result.settling;
  j["cache_hits"] = result.cache_hits;
  j["wall_s"] = result.wall_s;
  j["verdict"] = result.verdict;
  j["verdict_kind"] = optim::VerdictKindName(result.verdict_kind);
  j["base"] = result.base_label;
  j["node_mode"] = slam::NameOf(result.node_mode);
  j["changes"] = result.changes;
  j["how_to_load"] = result.how_to_load;
  j["recommended_share"] = result.recommended_share;
  j["lowest_error"] =
      result.lowest_error_label.empty() ? nlohmann::json(nullptr) : nlohmann::json(result.lowest_error_label);
  j["settings"] = result.settings.is_null() ? nlohmann::json::object() : result.settings;
  j["search_space"] = SearchSpaceJson(result.space);
  j["log"] = result.source.log_label;
  j["input"] = result.source.log_input;
  j["scans_not_used"] = ScanLossesJson(result.source.scans_not_used);
  j["relations"] =
      result.source.relations_label.empty() ? nlohmann::json(nullptr) : nlohmann::json(result.source.relations_label);
  if (result.base_front_end) {
    nlohmann::json front_end = FrontEndEvidenceJson(result.base_front_end->evidence);
    front_end["choice"] = result.base_front_end->choice;
    front_end["informed_start"] = result.base_front_end->informed_start;
    j["base_front_end"] = front_end;
  }
  j["history"] = HistoryJson(result);
  if (result.equivalent_region) {
    const optim::EquivalentRegion& e = *result.equivalent_region;
    nlohmann::json ranges = nlohmann::json::object();
    for (const optim::ParameterRange& r : e.ranges) ranges[r.name] = {r.lower, r.upper};
    j["equivalent_region"] = {{"tolerance", e.tolerance}, {"loop_closures", e.loop_closures},
                              {"members", e.members},     {"evaluated", e.evaluated},
                              {"ranges", ranges},         {"statement", e.Describe()}};
  } else {
    j["equivalent_region"] = nullptr;
  }
  if (correlation) {
    nlohmann::json c = {{"parameter_sets", correlation->parameter_sets}};
    for (const auto& o : correlation->objectives) {
      c[o.objective] = {{"rho", o.spearman.defined ? nlohmann::json(o.spearman.rho) : nlohmann::json(nullptr)},
                        {"n", o.spearman.n},
                        {"reading", o.reading}};
    }
    j["error_correlation"] = c;
  }
  return j;
}

}  // namespace slamtune::report
