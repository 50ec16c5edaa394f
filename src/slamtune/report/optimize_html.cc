// report.html (optimize_html.h).
#include "slamtune/io/log_summary.h"
#include "slamtune/report/optimize_html.h"

#include <fmt/format.h>

#include <cmath>
#include <filesystem>

#include "slamtune/report/html_page.h"
#include "slamtune/report/optimize_tables.h"
#include "slamtune/report/report_text.h"
#include "slamtune/report/tables.h"

namespace slamtune::report {

const char* const kObjectivesCaveat =
    "The objectives are computed from the map alone, without ground truth. "
    "Measured on real logs, they separate runs whose map broke (doubled walls, smeared corridors, a wing turned "
    "against the rest: more corners, more enclosed areas, more scan end points the map overrules) from working runs "
    "very reliably. "
    "They barely rank working runs that differ by a millimetre or two of trajectory error: among parameter sets "
    "that all close their loops, a lower objective is not evidence of a more accurate map. Read the "
    "recommendation as \"closes the loops of this log robustly\", and use ground-truth relations when a finer "
    "ranking matters.";

namespace {

bool Ok(const optim::EvaluationRecord& r) { return r.status == "ok"; }

std::string Short(double v) { return fmt::format("{:.5g}", v); }

std::string Seconds(double s) {
  if (s < 120.0) return fmt::format("{:.1f} s", s);
  return fmt::format("{:.1f} min ({:.0f} s)", s / 60.0, s);
}

std::string SettingText(const nlohmann::json& v) { return v.is_string() ? v.get<std::string>() : v.dump(); }

void RunSection(HtmlPage& page, const optim::OptimizeResult& r) {
  page.Heading(2, "Run");
  std::vector<std::pair<std::string, std::string>> items = {
      {"log", r.log_path},
  };
  for (const auto& row : io::InputRows(r.log_input)) items.push_back(row);
  items.insert(items.end(), {
      {"relations (ground truth)", r.relations_path.empty() ? "none" : r.relations_path},
      {"generations", r.settling.empty() ? std::to_string(r.generations_run) : r.settling},
      {"SLAM runs (evaluations)", std::to_string(r.evaluation_count)},
      {"requests served from the cache", std::to_string(r.cache_hits)},
      {"wall time", Seconds(r.wall_s)},
  });
  if (r.settings.is_object() && r.settings.contains("population")) {
    items.push_back({"recommended share", fmt::format("{} of {} individuals of the final population",
                                                      r.recommended_share, SettingText(r.settings["population"]))});
  } else {
    items.push_back({"recommended share", fmt::format("{} individuals of the final population", r.recommended_share)});
  }
  page.KeyValues(items);
}

void VerdictSection(HtmlPage& page, const optim::OptimizeResult& r) {
  page.Heading(2, "Verdict");
  page.Paragraph(r.verdict.empty() ? "No verdict was given." : r.verdict, "verdict");
  if (!r.how_to_load.empty()) {
    page.Paragraph(r.changes.empty() ? "Keep " + r.base_label + ": the parameter files repeat it unchanged."
                                     : "Changes from " + r.base_label + ":");
    if (!r.changes.empty()) page.List(r.changes);
    page.Paragraph("To run it on the robot:");
    page.List(r.how_to_load);
  }
  if (!r.lowest_error_label.empty()) {
    page.Paragraph("Against the ground-truth relations, the candidate with the lowest mean translational error is \"" +
                   r.lowest_error_label + "\".");
  }
}

void FrontEndSection(HtmlPage& page, const optim::OptimizeResult& r, const OptimizeFigures& f) {
  if (!r.base_front_end) return;
  const optim::BaseFrontEnd& fe = *r.base_front_end;
  page.Heading(2, "Front end of the base configuration");
  page.Paragraph(fe.choice);
  if (!f.front_end.empty()) {
    page.Image(f.front_end, "sequential match responses along the log",
               "Each sequential match of the base configuration's run: its response, those that ended at the edge "
               "of the search window or heading range, and the breaks (front_end.png).");
  }
  std::vector<std::vector<std::string>> rows;
  for (const slam::SuspectStretch& s : fe.evidence.stretches) {
    rows.push_back({fmt::format("{}-{}", s.first_log_index, s.last_log_index),
                    fmt::format("{:.1f}-{:.1f}", s.first_time, s.last_time), std::to_string(s.at_edge),
                    std::to_string(s.low_response), fmt::format("{:.2f}", s.min_response),
                    s.strong() ? "yes" : "no"});
  }
  if (!rows.empty()) {
    page.Table({"log scans", "seconds into the log", "at the search's edge", "collapsed response", "lowest response",
                "break"},
               rows);
  }
}

void CandidatesSection(HtmlPage& page, const optim::OptimizeResult& r, bool gt) {
  page.Heading(2, "Candidates");
  std::vector<std::string> header = {"label", "how it was chosen", "parameters", "status"};
  for (std::size_t k = 0; k < r.objectives.size(); ++k) header.push_back(ObjectiveAt(r, k).short_name);
  header.push_back("loop closures");
  if (gt) header.insert(header.end(), {"trans. error (m)", "rot. error (deg)", "relations"});
  std::vector<std::vector<std::string>> rows;
  for (const auto* c : CandidatesInReportOrder(r)) {
    const auto& e = c->record;
    std::vector<std::string> row = {c->label, c->description, ParamSummary(e.params, r.space),
                                    Ok(e) ? "ok" : "failed: " + e.reason};
    for (double v : r.objectives.Values(e)) row.push_back(Ok(e) ? Short(v) : "");
    row.push_back(Ok(e) ? std::to_string(e.loop_closures) : "");
    if (gt) {
      if (e.has_gt) {
        row.insert(row.end(), {FormatMeanStd(e.trans_mean_m, e.trans_std_m), FormatMeanStd(e.rot_mean_deg, e.rot_std_deg),
                               std::to_string(e.relations_used)});
      } else {
        row.insert(row.end(), {"", "", ""});
      }
    }
    rows.push_back(std::move(row));
  }
  page.Table(header, rows);
  page.Paragraph(ObjectiveLegend(r.objectives) + " (all minimised). Parameters: " +
                     std::string("r = loop_search_maximum_distance (m), g = loop_match_minimum_chain_size."),
                 "note");

  page.Heading(3, "Loop closures: log scan indices");
  std::vector<std::vector<std::string>> scans;
  for (const auto* c : CandidatesInReportOrder(r)) {
    const std::string list = JoinScans(c->record.loop_scans);
    scans.push_back({c->label, std::to_string(c->record.loop_scans.size()), list.empty() ? "(none)" : list});
  }
  page.Table({"label", "loop closures", "scan indices"}, scans);
}

void CorrelationSection(HtmlPage& page, const OptimizeFigures& f, const ErrorCorrelationSummary& c) {
  page.Heading(2, "Do the objectives track the true error on this log?");
  if (!f.objective_vs_error.empty()) {
    page.Image(f.objective_vs_error, "objectives against translational error",
               "Each objective against the mean translational error of every distinct parameter set (objective_vs_error.png).");
  }
  std::vector<std::vector<std::string>> rows;
  for (const auto& o : c.objectives) {
    rows.push_back({o.objective, o.spearman.defined ? fmt::format("{:.3f}", o.spearman.rho) : "undefined",
                    std::to_string(o.spearman.n), o.reading});
  }
  page.Table({"objective", "Spearman rho", "parameter sets", "reading"}, rows);
  page.Paragraph(c.statement);
}

}  // namespace

std::string OptimizeHtml(const optim::OptimizeResult& r, const OptimizeFigures& f,
                         const std::optional<ErrorCorrelationSummary>& correlation,
                         const std::vector<std::string>& files) {
  const std::string log_name = std::filesystem::path(r.log_path).filename().string();
  HtmlPage page("slamtune optimize: " + log_name);
  page.Heading(1, "slamtune optimize: " + (log_name.empty() ? std::string("(no log named)") : log_name));
  RunSection(page, r);
  VerdictSection(page, r);
  FrontEndSection(page, r, f);
  CandidatesSection(page, r, correlation.has_value());

  page.Heading(2, "Maps");
  if (!f.maps.empty()) {
    page.Image(f.maps, "maps of the candidates",
               "The candidates' maps, cropped to the mapped area and scaled to a common height (maps_side_by_side.png; "
               "full maps as map_<label>.pgm/.yaml).");
  } else {
    page.Paragraph("No candidate to show.");
  }

  page.Heading(2, "Population in objective space");
  for (const auto& [generation, png] : f.populations) {
    page.Image(png, fmt::format("population of generation {}", generation),
               fmt::format("Generation {} (population_gen{}.png).", generation, generation));
  }
  if (!f.evolution.empty()) {
    page.Image(f.evolution, "population over the generations", "All snapshots overlaid (population_evolution.png).");
  }
  if (f.populations.empty()) page.Paragraph("No population snapshot was recorded.");

  if (correlation) CorrelationSection(page, f, *correlation);

  page.Heading(2, "What the objectives can tell");
  page.Paragraph(kObjectivesCaveat, "note");

  page.Heading(2, "Settings");
  std::vector<std::pair<std::string, std::string>> settings;
  if (r.settings.is_object()) {
    for (const auto& [key, value] : r.settings.items()) settings.push_back({key, SettingText(value)});
  }
  if (!settings.empty()) page.KeyValues(settings);
  std::vector<std::vector<std::string>> dims;
  for (const auto& d : r.space.dimensions) {
    dims.push_back({d.name + " (" + ShortParamName(d.name) + ")", FormatParam(d.lower), FormatParam(d.upper),
                    d.integer ? "int" : "real"});
  }
  for (const auto& [name, value] : r.space.fixed) dims.push_back({name, FormatParam(value), FormatParam(value), "fixed"});
  page.Table({"parameter", "lower", "upper", "type"}, dims);

  page.Heading(2, "Files");
  page.List(files);
  return page.Finish();
}

}  // namespace slamtune::report
