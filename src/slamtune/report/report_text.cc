// Shared names and texts (report_text.h).
#include "slamtune/report/report_text.h"

#include <cmath>

#include <fmt/format.h>

#include "slamtune/common/error.h"
#include "slamtune/report/tables.h"

namespace slamtune::report {

const optim::ObjectiveInfo& ObjectiveAt(const optim::OptimizeResult& result, std::size_t k) {
  SLAMTUNE_CHECK(k < result.objectives.size());
  return optim::InfoOf(result.objectives.objectives()[k]);
}

std::string ObjectiveLegend(const optim::ObjectiveSet& objectives) {
  std::string out;
  for (optim::Objective o : objectives.objectives()) {
    const optim::ObjectiveInfo& info = optim::InfoOf(o);
    std::string title = info.title;
    title = title.substr(0, title.find(" ("));
    out += fmt::format("{}{} = {}", out.empty() ? "" : ", ", info.short_name, title);
  }
  return out;
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
