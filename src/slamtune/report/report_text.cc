// Shared names and texts (report_text.h).
#include "slamtune/report/report_text.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/report/tables.h"
#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::report {

const optim::RecordFigure& ObjectiveAt(const optim::OptimizeResult& result, std::size_t k) {
  SLAMTUNE_CHECK(k < result.objectives.size());
  return optim::InfoOf(result.objectives.objectives()[k]);
}

std::string ObjectiveLegend(const optim::ObjectiveSet& objectives) {
  std::string out;
  for (optim::Objective o : objectives.objectives()) {
    const optim::RecordFigure& info = optim::InfoOf(o);
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

const optim::Candidate& CandidateGroup::shown() const {
  SLAMTUNE_CHECK(!members.empty());
  for (const auto* c : members)
    if (c->map.width > 0 && c->map.height > 0) return *c;
  return *members.front();
}

std::vector<CandidateGroup> MergedCandidates(const optim::OptimizeResult& result) {
  const auto same = [](const optim::EvaluationRecord& a, const optim::EvaluationRecord& b) {
    return !a.key.empty() && !b.key.empty() ? a.key == b.key : a.params == b.params;
  };
  std::vector<CandidateGroup> groups;
  for (const auto* c : CandidatesInReportOrder(result)) {
    CandidateGroup* found = nullptr;
    for (auto& g : groups)
      if (same(g.members.front()->record, c->record)) found = &g;
    if (found) {
      found->members.push_back(c);
      found->label += " = " + c->label;
    } else {
      groups.push_back({c->label, {c}});
    }
  }
  return groups;
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

std::string ParamUnit(const std::string& ros_name) {
  const slam::ParamInfo* info = slam::FindParam(ros_name);
  if (info == nullptr) return "";
  // The meaning starts with "UNIT; " when the parameter has one.
  const std::string meaning = info->meaning;
  const std::size_t semicolon = meaning.find(';');
  if (semicolon == std::string::npos || semicolon == 0 || semicolon > 4) return "";
  const std::string unit = meaning.substr(0, semicolon);
  return unit.find(' ') == std::string::npos ? unit : "";
}

std::string Readable(double value, int significant, int max_decimals) {
  if (!std::isfinite(value)) return FormatNumber(value);
  significant = std::max(significant, 1);
  max_decimals = std::max(max_decimals, 0);
  const double magnitude = std::abs(value);
  if (magnitude != 0.0 && (magnitude < 1e-4 || magnitude >= 1e9)) {
    return fmt::format("{:.{}e}", value, significant - 1);
  }
  const int exponent = magnitude == 0.0 ? 0 : static_cast<int>(std::floor(std::log10(magnitude)));
  const int decimals = std::clamp(significant - 1 - exponent, 0, max_decimals);
  std::string out = fmt::format("{:.{}f}", value, decimals);
  if (out.find('.') != std::string::npos) {
    while (out.back() == '0') out.pop_back();
    if (out.back() == '.') out.pop_back();
  }
  if (out == "-0") out = "0";
  return out;
}

std::string Metres(double metres) { return Readable(metres, 12, 3); }

std::string FormatParam(double value) {
  if (std::isfinite(value) && value == std::round(value) && std::abs(value) < 1e15) {
    return std::to_string(static_cast<long long>(value));
  }
  return Readable(value, 4, 3);
}

std::vector<std::string> SummarisedParams(const std::map<std::string, double>& params,
                                          const optim::SearchSpace& space) {
  std::vector<std::string> names;
  if (space.dimensions.empty()) {
    for (const auto& entry : params) names.push_back(entry.first);
  } else {
    for (const auto& d : space.dimensions) {
      if (params.contains(d.name)) names.push_back(d.name);
    }
  }
  return names;
}

std::string ParamSummary(const std::map<std::string, double>& params, const optim::SearchSpace& space) {
  std::string out;
  for (const std::string& name : SummarisedParams(params, space)) {
    if (!out.empty()) out += ' ';
    out += ShortParamName(name) + "=" + FormatParam(params.at(name));
  }
  return out;
}

std::string ParamLegend(const std::vector<std::string>& ros_names) {
  std::string out;
  for (const std::string& name : ros_names) {
    const std::string symbol = ShortParamName(name);
    if (symbol == name) continue;
    const std::string unit = ParamUnit(name);
    if (!out.empty()) out += ", ";
    out += symbol + " = " + name + (unit.empty() ? "" : " (" + unit + ")");
  }
  return out;
}

bool HasGroundTruth(const optim::OptimizeResult& result) {
  if (!result.source.relations_label.empty()) return true;
  for (const auto& e : result.evaluations)
    if (e.has_gt) return true;
  for (const auto& c : result.candidates)
    if (c.record.has_gt) return true;
  return false;
}

}  // namespace slamtune::report
