// Shared names and texts (report_text.h).
#include "slamtune/report/report_text.h"

#include <cmath>

#include "slamtune/report/tables.h"

namespace slamtune::report {

std::array<double, 3> ObjectiveValues(const optim::EvaluationRecord& record) {
  return {record.occupied_ratio, record.corner_pixels, record.enclosed_areas};
}

bool IsFailureScore(const std::vector<double>& objectives) {
  if (objectives.size() != kObjectives.size()) return true;
  for (double v : objectives)
    if (!std::isfinite(v)) return true;
  // EvaluationRecord::Objectives() scores a failed run {1, 1e9, 1e9}.
  return objectives[1] >= 1e9 || objectives[2] >= 1e9;
}

std::vector<const optim::Candidate*> CandidatesInReportOrder(const optim::OptimizeResult& result) {
  static const std::array<const char*, 4> kOrder = {"recommended", "knee", "default", "worst"};
  std::vector<const optim::Candidate*> out;
  for (const char* label : kOrder)
    if (const optim::Candidate* c = result.Find(label)) out.push_back(c);
  for (const auto& c : result.candidates) {
    bool listed = false;
    for (const auto* o : out) listed = listed || o == &c;
    if (!listed) out.push_back(&c);
  }
  return out;
}

std::string ShortParamName(const std::string& ros_name) {
  static const std::map<std::string, std::string> kShort = {
      {"loop_search_maximum_distance", "r"},
      {"loop_match_minimum_chain_size", "g"},
      {"loop_match_minimum_response_coarse", "p"},
      {"loop_match_maximum_variance_coarse", "q"},
  };
  const auto it = kShort.find(ros_name);
  return it == kShort.end() ? ros_name : it->second;
}

std::string FormatParam(double value) {
  if (std::isfinite(value) && value == std::round(value) && std::abs(value) < 1e15) {
    return std::to_string(static_cast<long long>(value));
  }
  return FormatNumber(value);
}

std::string ParamSummary(const std::map<std::string, double>& params, const optim::SearchSpace& space) {
  std::string out;
  auto add = [&](const std::string& name) {
    const auto it = params.find(name);
    if (it == params.end()) return;
    if (!out.empty()) out += ' ';
    out += ShortParamName(name) + "=" + FormatParam(it->second);
  };
  if (space.dimensions.empty()) {
    for (const auto& [name, value] : params) add(name);
  } else {
    for (const auto& d : space.dimensions) add(d.name);
  }
  return out;
}

bool HasGroundTruth(const optim::OptimizeResult& result) {
  if (!result.relations_path.empty()) return true;
  for (const auto& e : result.evaluations)
    if (e.has_gt) return true;
  for (const auto& c : result.candidates)
    if (c.record.has_gt) return true;
  return false;
}

}  // namespace slamtune::report
