// The paper's tables as CSV (optimize_tables.h).
#include "slamtune/report/optimize_tables.h"

#include <algorithm>
#include <set>

#include "slamtune/report/report_text.h"

namespace slamtune::report {
namespace {

std::string Param(const std::map<std::string, double>& params, const std::string& name) {
  const auto it = params.find(name);
  return it == params.end() ? "" : FormatNumber(it->second);
}

std::vector<std::string> ErrorCells(const optim::EvaluationRecord& r) {
  if (!r.has_gt) return {"", "", "", "", ""};
  return {FormatNumber(r.trans_mean_m), FormatNumber(r.trans_std_m), FormatNumber(r.rot_mean_deg),
          FormatNumber(r.rot_std_deg), std::to_string(r.relations_used)};
}

}  // namespace

std::string FigureCell(const optim::EvaluationRecord& record, double value) {
  return record.ok() ? FormatNumber(value) : "";
}

std::string JoinScans(const std::vector<int>& scans) {
  std::string out;
  for (int s : scans) {
    if (!out.empty()) out += ' ';
    out += std::to_string(s);
  }
  return out;
}

std::vector<std::string> ParameterColumns(const std::vector<optim::EvaluationRecord>& records,
                                          const optim::SearchSpace& space) {
  std::vector<std::string> columns;
  std::set<std::string> seen;
  auto add = [&](const std::string& name) {
    if (seen.insert(name).second) columns.push_back(name);
  };
  for (const auto& d : space.dimensions) add(d.name);
  for (const auto& [name, value] : space.fixed) add(name);
  std::set<std::string> others;  // sorted, so the column order does not depend on record order
  for (const auto& r : records)
    for (const auto& [name, value] : r.params)
      if (!seen.count(name)) others.insert(name);
  for (const auto& name : others) add(name);
  return columns;
}

CsvTable ParamsTable(const optim::OptimizeResult& result) {
  std::vector<optim::EvaluationRecord> records;
  for (const auto* c : CandidatesInReportOrder(result)) records.push_back(c->record);
  std::vector<std::string> names;
  for (const auto& d : result.space.dimensions) names.push_back(d.name);
  if (names.empty()) names = ParameterColumns(records, result.space);
  CsvTable t;
  t.header = {"label"};
  t.header.insert(t.header.end(), names.begin(), names.end());
  for (const auto* c : CandidatesInReportOrder(result)) {
    std::vector<std::string> row = {c->label};
    for (const auto& n : names) row.push_back(Param(c->record.params, n));
    t.AddRow(std::move(row));
  }
  return t;
}

CsvTable ObjectivesTable(const optim::OptimizeResult& result) {
  CsvTable t;
  t.header = {"label", "eta", "eta_known", "corner_pixels", "corners", "enclosed_areas", "contours", "unbacked_hits"};
  for (const auto* c : CandidatesInReportOrder(result)) {
    const auto& r = c->record;
    t.AddRow({c->label, FigureCell(r, r.occupied_ratio), FigureCell(r, r.occupied_ratio_known),
              FigureCell(r, r.corner_pixels), FigureCell(r, r.corners), FigureCell(r, r.enclosed_areas),
              FigureCell(r, r.contours), FigureCell(r, optim::ValueOf(r, optim::Objective("unbacked_hits")))});
  }
  return t;
}

CsvTable LoopClosuresTable(const optim::OptimizeResult& result) {
  CsvTable t;
  t.header = {"label", "loop_closures"};
  for (const auto* c : CandidatesInReportOrder(result)) {
    t.AddRow({c->label, c->record.ok() ? std::to_string(c->record.loop_closures) : ""});
  }
  return t;
}

CsvTable LoopScansTable(const optim::OptimizeResult& result) {
  CsvTable t;
  t.header = {"label", "scan_indices"};
  for (const auto* c : CandidatesInReportOrder(result)) t.AddRow({c->label, JoinScans(c->record.loop_scans)});
  return t;
}

CsvTable ErrorsTable(const optim::OptimizeResult& result) {
  CsvTable t;
  t.header = {"label", "trans_mean_m", "trans_std_m", "rot_mean_deg", "rot_std_deg", "relations_used"};
  for (const auto* c : CandidatesInReportOrder(result)) {
    std::vector<std::string> row = {c->label};
    for (auto& cell : ErrorCells(c->record)) row.push_back(std::move(cell));
    t.AddRow(std::move(row));
  }
  return t;
}

CsvTable EvaluationsTable(const std::vector<optim::EvaluationRecord>& evaluations, const optim::SearchSpace& space) {
  const std::vector<std::string> params = ParameterColumns(evaluations, space);
  CsvTable t;
  t.header = {"index"};
  t.header.insert(t.header.end(), params.begin(), params.end());
  t.header.insert(t.header.end(), {"status", "reason"});
  for (const optim::RecordFigure& figure : optim::RecordFigures()) t.header.push_back(figure.key);
  t.header.insert(t.header.end(), {"nodes", "loop_closures", "wall_s", "trans_mean_m", "trans_std_m", "rot_mean_deg",
                                   "rot_std_deg", "relations_used"});
  for (std::size_t i = 0; i < evaluations.size(); ++i) {
    const auto& r = evaluations[i];
    std::vector<std::string> row = {std::to_string(i)};
    for (const auto& p : params) row.push_back(Param(r.params, p));
    row.insert(row.end(), {NameOf(r.status), r.reason});
    for (const optim::RecordFigure& figure : optim::RecordFigures())
      row.push_back(FigureCell(r, optim::FigureValue(figure, r)));
    row.insert(row.end(), {r.ok() ? std::to_string(r.nodes) : "", r.ok() ? std::to_string(r.loop_closures) : "",
                           FormatNumber(r.wall_s)});
    for (auto& cell : ErrorCells(r)) row.push_back(std::move(cell));
    t.AddRow(std::move(row));
  }
  return t;
}

}  // namespace slamtune::report
