// report.html (optimize_html.h).
#include "slamtune/report/optimize_html.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include "slamtune/io/log_summary.h"
#include "slamtune/report/figures/optimize_figures.h"
#include "slamtune/report/html_page.h"
#include "slamtune/report/optimize_tables.h"
#include "slamtune/report/report_text.h"
#include "slamtune/report/tables.h"
#include "slamtune/report/verdict_html.h"

namespace slamtune::report {

const char* const kObjectivesCaveat =
    "The objectives are computed from the map alone, without ground truth. "
    "Measured on four real logs and four simulated buildings, they separate runs whose map broke (doubled walls, "
    "smeared corridors, a wing turned against the rest: more corners, more enclosed areas or wall cells, more scan "
    "end points the map overrules) from working runs, though not on every input (docs/metrics.md of the project "
    "lists where they fail). "
    "They barely rank working runs that differ by a millimetre or two of trajectory error: among parameter sets "
    "that all close their loops, a lower objective is not evidence of a more accurate map. Read the "
    "recommendation as \"closes the loops of this log robustly\", and use ground-truth relations when a finer "
    "ranking matters.";

namespace {

std::string Short(double v) { return Readable(v, 4); }

std::string Seconds(double s) {
  if (s < 120.0) return fmt::format("{:.1f} s", s);
  return fmt::format("{:.1f} min ({:.0f} s)", s / 60.0, s);
}

// A setting's value in plain text: numbers Readable, lists joined, strings as they are.
std::string SettingText(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_boolean()) return v.get<bool>() ? "yes" : "no";
  if (v.is_number_integer() || v.is_number_unsigned()) return v.dump();
  if (v.is_number()) return Readable(v.get<double>(), 6);
  if (v.is_null()) return "none";
  if (v.is_array()) {
    std::string out;
    for (const auto& e : v) out += (out.empty() ? "" : ", ") + SettingText(e);
    return out.empty() ? "(none)" : out;
  }
  std::string out;  // an object inside a list: "key: value; ..."
  for (const auto& [key, value] : v.items()) out += (out.empty() ? "" : "; ") + key + ": " + SettingText(value);
  return out;
}

// Nested settings as "parent.child" rows, one per leaf value.
void FlattenSettings(const nlohmann::json& v, const std::string& prefix,
                     std::vector<std::pair<std::string, std::string>>& rows) {
  if (v.is_object() && !v.empty()) {
    for (const auto& [key, value] : v.items()) FlattenSettings(value, prefix.empty() ? key : prefix + "." + key, rows);
    return;
  }
  rows.push_back({prefix, SettingText(v)});
}

void RunSection(HtmlPage& page, const optim::OptimizeResult& r) {
  page.Heading(2, "Run");
  std::vector<std::pair<std::string, std::string>> items = {
      {"log", r.source.log_label},
      {"node modelled", slam::LaunchOf(r.node_mode)},
  };
  for (const auto& row : io::InputRows(r.source.log_input)) items.push_back(row);
  items.insert(items.end(),
               {
                   {"relations (ground truth)", r.source.relations_label.empty() ? "none" : r.source.relations_label},
                   {"generations", r.settling.empty() ? std::to_string(r.generations_run) : r.settling},
                   {"SLAM runs (evaluations)", std::to_string(r.evaluation_count)},
                   {"requests served from the cache", std::to_string(r.cache_hits)},
                   {"wall time", Seconds(r.wall_s)},
               });
  if (r.population > 0) {
    items.push_back({"recommended share",
                     fmt::format("{} of {} individuals of the final population", r.recommended_share, r.population)});
  } else {
    items.push_back({"recommended share", fmt::format("{} individuals of the final population", r.recommended_share)});
  }
  page.KeyValues(items);
}

// Every evaluation in a table the reader sorts by clicking a header; collapsed when long.
void EvaluationsSection(HtmlPage& page, const optim::OptimizeResult& r, bool gt) {
  if (r.evaluations.empty()) return;
  page.Heading(2, "Every evaluation", "evaluations");
  std::vector<std::string> header = {"#"};
  for (const optim::Dimension& d : r.space.dimensions) header.push_back(d.name);
  for (std::size_t k = 0; k < r.objectives.size(); ++k) header.push_back(ObjectiveAt(r, k).short_name);
  header.push_back("loop closures");
  if (gt) header.insert(header.end(), {"trans. error (m)", "rot. error (deg)"});
  header.push_back("status");
  std::vector<std::vector<std::string>> rows;
  for (std::size_t i = 0; i < r.evaluations.size(); ++i) {
    const optim::EvaluationRecord& e = r.evaluations[i];
    std::vector<std::string> row = {std::to_string(i + 1)};
    for (const optim::Dimension& d : r.space.dimensions) {
      const auto it = e.params.find(d.name);
      row.push_back(it == e.params.end() ? "" : FormatParam(it->second));
    }
    for (double v : r.objectives.Values(e)) row.push_back(e.ok() ? Short(v) : "");
    row.push_back(e.ok() ? std::to_string(e.loop_closures) : "");
    if (gt) {
      row.push_back(e.has_gt ? Metres(e.trans_mean_m) : "");
      row.push_back(e.has_gt ? Readable(e.rot_mean_deg, 3) : "");
    }
    row.push_back(e.ok() ? "ok" : "failed: " + e.reason);
    rows.push_back(std::move(row));
  }
  const bool long_table = rows.size() > 20;
  if (long_table) {
    page.BeginDetails(
        fmt::format("All {} evaluations, in the order they ran (click to open; click a column header "
                    "to sort)",
                    rows.size()));
  } else {
    page.Paragraph("In the order they ran; click a column header to sort by it (again: the other way).", "note");
  }
  page.SortableTable(header, rows);
  if (long_table) page.EndDetails();
  page.Paragraph("The same rows, with every map figure, are in evaluations.csv. " + ObjectiveLegend(r.objectives) +
                     " (all minimised).",
                 "note");
}

// How the search progressed, generation by generation (optim/optimization_history.h).
void HistorySection(HtmlPage& page, const optim::OptimizeResult& r, const OptimizeFigures& f) {
  if (f.history.empty()) return;
  page.Heading(2, "How the search progressed", "history");
  page.Image(f.history, "best objectives and hypervolume per generation",
             fmt::format("The best value of each objective in every generation (0 is the initial random population), "
                         "and the hypervolume of each generation's non-dominated front: the objectives normalised "
                         "to [0, 1] by their ranges over all generations, the volume they dominate up to {} in "
                         "each (largest possible value {}). Failed runs are left out. A curve that has flattened "
                         "says more generations would change little (history.png; the values are in results.json, "
                         "\"history\").",
                         Readable(optim::kHypervolumeReference),
                         Readable(std::pow(optim::kHypervolumeReference, static_cast<double>(r.objectives.size())))));
}

// The panel of the candidate labelled `label` (alone or merged, "recommended = knee"), or null.
const OptimizeFigures::MapPanel* PanelOf(const OptimizeFigures& f, const std::string& label) {
  for (const OptimizeFigures::MapPanel& p : f.map_panels) {
    if (p.label == label || p.label.rfind(label + " ", 0) == 0 || p.label.find(" " + label) != std::string::npos) {
      return &p;
    }
  }
  return nullptr;
}

// What a person sees before scrolling: the verdict, then the base configuration's map (with
// where its front end broke marked, when it did) beside the recommended map.
void FirstScreen(HtmlPage& page, const optim::OptimizeResult& r, const OptimizeFigures& f) {
  page.Paragraph(r.verdict.empty() ? "No verdict was given." : r.verdict, "verdict");
  std::vector<HtmlPage::Figure> figures;
  if (!f.front_end_map.empty()) {
    figures.push_back({f.front_end_map, "the base configuration's map, where its front end failed marked",
                       "Your base configuration (" + r.base_label +
                           "): where its front end lost its place is marked (front_end_map.png).",
                       "front_end_map.png"});
  } else if (const auto* base = PanelOf(f, "default")) {
    figures.push_back({base->png, "the base configuration, mapped", base->caption, base->file});
  }
  if (const auto* recommended = PanelOf(f, "recommended");
      recommended != nullptr && figures.size() == 1 && recommended->png != figures.front().png) {
    figures.push_back({recommended->png, "the recommended map", recommended->caption, recommended->file});
  }
  if (!figures.empty()) page.FigureGrid(figures, 2, "first");
}

void FrontEndSection(HtmlPage& page, const optim::OptimizeResult& r, const OptimizeFigures& f) {
  if (!r.base_front_end) return;
  const optim::BaseFrontEnd& fe = *r.base_front_end;
  page.Heading(2, "Front end of the base configuration", "front-end");
  page.Paragraph(fe.choice);
  if (!fe.informed_start.empty()) page.Paragraph(fe.informed_start);
  if (!f.front_end_map.empty()) {
    page.FigureGrid({{f.front_end_map, "where the base configuration's front end failed, on its map",
                      "Where it happened, on the base configuration's own map (front_end_map.png; click for the "
                      "full-size image): the robot's path in blue, stretches where the scans saw structure in one "
                      "direction only in orange, suspect stretches in magenta, and each break as a red ring "
                      "labelled with its log scan index.",
                      "front_end_map.png"}},
                    1);
  }
  if (!f.front_end.empty()) {
    page.Image(f.front_end, "sequential match responses along the log",
               "Each sequential match of the base configuration's run: its response, those that ended at the edge "
               "of the search window or heading range, and the breaks (front_end.png).");
  }
  std::vector<std::vector<std::string>> rows;
  for (const slam::SuspectStretch& s : fe.evidence.stretches) {
    rows.push_back({fmt::format("{}-{}", s.first_log_index, s.last_log_index),
                    fmt::format("{:.1f}-{:.1f}", s.first_time, s.last_time), std::to_string(s.at_edge),
                    std::to_string(s.low_response), fmt::format("{:.2f}", s.min_response), s.strong() ? "yes" : "no"});
  }
  if (!rows.empty()) {
    page.Table(
        {"log scans", "seconds into the log", "at the search's edge", "collapsed response", "lowest response", "break"},
        rows);
  }
}

// The parameters the Candidates table shows (SummarisedParams), each once, in first-seen order.
std::vector<std::string> ShownParamNames(const optim::OptimizeResult& r) {
  std::vector<std::string> names;
  for (const auto* c : CandidatesInReportOrder(r)) {
    for (std::string& name : SummarisedParams(c->record.params, r.space)) {
      if (std::find(names.begin(), names.end(), name) == names.end()) names.push_back(std::move(name));
    }
  }
  return names;
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
                                    e.ok() ? "ok" : "failed: " + e.reason};
    for (double v : r.objectives.Values(e)) row.push_back(e.ok() ? Short(v) : "");
    row.push_back(e.ok() ? std::to_string(e.loop_closures) : "");
    if (gt) {
      if (e.has_gt) {
        row.insert(row.end(), {FormatMeanStd(e.trans_mean_m, e.trans_std_m),
                               FormatMeanStd(e.rot_mean_deg, e.rot_std_deg), std::to_string(e.relations_used)});
      } else {
        row.insert(row.end(), {"", "", ""});
      }
    }
    rows.push_back(std::move(row));
  }
  page.Table(header, rows);
  const std::string params = ParamLegend(ShownParamNames(r));
  page.Paragraph(
      ObjectiveLegend(r.objectives) + " (all minimised)." + (params.empty() ? "" : " Parameters: " + params + "."),
      "note");

  page.Heading(3, "Loop closures: log scan indices");
  std::vector<std::vector<std::string>> scans;
  for (const auto* c : CandidatesInReportOrder(r)) {
    const std::string list = JoinScans(c->record.loop_scans);
    scans.push_back({c->label, std::to_string(c->record.loop_scans.size()), list.empty() ? "(none)" : list});
  }
  page.Table({"label", "loop closures", "scan indices"}, scans);
}

// What parameter_space.png shows and how to read it, by its view (optimize_figures.h).
std::string ParameterSpaceCaption(const optim::OptimizeResult& r) {
  const std::string objective = r.objectives.size() > 0 ? ObjectiveAt(r, 0).short_name : "the first objective";
  switch (ParameterSpaceViewOf(r)) {
    case ParameterSpaceView::kScatterGrid: {
      const bool gt = ParameterSpacePanels(r).back().colouring == SpaceColouring::kTranslationalError;
      return fmt::format(
          "Where the search went: every evaluated parameter set in the plane of the two searched parameters, drawn "
          "once per panel and coloured by the quarter of each objective it falls in (green the best quarter, purple "
          "the worst), by its number of loop closures (dark few, light many){}; failed runs are grey crosses. The "
          "candidates are marked in every panel. A region that is green in every objective's panel is a safe "
          "choice; where the panels disagree, the objectives trade off against each other. A candidate outside "
          "the search range widens the axes (the range is then outlined in grey) or, when far off, is drawn at "
          "the border as a triangle with its values in the legend (parameter_space.png).",
          gt ? " and by the quarter of its true translational error" : "");
    }
    case ParameterSpaceView::kParallelCoordinates:
      return fmt::format(
          "Where the search went, in parallel coordinates: one vertical axis per searched parameter, spanning its "
          "search range (symbols and full names in the Settings table below), and a last axis for {0}. Each "
          "successful parameter set is a line joining its values, coloured by the quarter of {0} it falls in "
          "(green the best quarter, drawn on top; purple the worst). The recommended set is the thick vermillion "
          "line, the default the thick black one; a value beyond an axis's range is drawn at its end with a "
          "triangle and the value. Where the green lines gather on part of an axis, that parameter matters for "
          "{0}; where they spread over the whole axis, it does not within its range (parameter_space.png).",
          objective);
    case ParameterSpaceView::kSlices:
      return fmt::format(
          "Where the search went: {} of every evaluated parameter set against the searched parameter, "
          "with the candidates marked (parameter_space.png).",
          objective);
    case ParameterSpaceView::kNone: break;
  }
  return "";
}

void CorrelationSection(HtmlPage& page, const OptimizeFigures& f, const ErrorCorrelationSummary& c) {
  page.Heading(2, "Do the objectives track the true error on this log?");
  if (!f.objective_vs_error.empty()) {
    page.Image(f.objective_vs_error, "objectives against translational error",
               "Each objective against the mean translational error of every distinct parameter set "
               "(objective_vs_error.png).");
  }
  std::vector<std::vector<std::string>> rows;
  for (const auto& o : c.objectives) {
    rows.push_back({o.objective, o.spearman.defined ? fmt::format("{:.3f}", o.spearman.rho) : "undefined",
                    std::to_string(o.spearman.n), o.reading});
  }
  page.Table({"objective", "Spearman rho", "parameter sets", "reading"}, rows);
  page.Paragraph(c.statement);
}

void MapsSection(HtmlPage& page, const OptimizeFigures& f) {
  page.Heading(2, "Maps", "maps");
  if (f.map_panels.empty()) {
    page.Paragraph("No candidate to show.");
    return;
  }
  std::vector<HtmlPage::Figure> figures;
  for (const auto& m : f.map_panels) figures.push_back({m.png, "map of " + m.label, m.caption, m.file});
  page.FigureGrid(figures, 2);
  page.Paragraph(
      "Each map is cropped to its mapped area, with a scale bar under it. Vermillion lines join the two "
      "robot poses of each loop closure. Click a map for the full-size image; the maps are also written as "
      "map_<label>.pgm/.yaml for map_server, and all together as maps_side_by_side.png.",
      "note");
}

void PopulationSection(HtmlPage& page, const OptimizeFigures& f) {
  page.Heading(2, "Population in objective space", "population");
  if (!f.populations.empty()) {
    page.Paragraph(
        "Every panel uses the same axes, fitted to the non-dominated front of all generations shown (black "
        "diamonds mark each generation's front) and reaching one front's width beyond it, so the generations "
        "compare directly; a panel's title counts the individuals that lie outside its axes (usually runs "
        "whose map broke).");
  }
  std::vector<HtmlPage::Figure> generations;
  for (const auto& [generation, png] : f.populations) {
    generations.push_back({png, fmt::format("population of generation {}", generation),
                           fmt::format("Generation {} (population_gen{}.png).", generation, generation),
                           fmt::format("population_gen{}.png", generation)});
  }
  if (!generations.empty()) page.FigureGrid(generations, 1);
  if (!f.evolution.empty()) {
    page.Image(f.evolution, "population over the generations", "All snapshots overlaid (population_evolution.png).");
  }
  if (f.populations.empty()) page.Paragraph("No population snapshot was recorded.");
}

void SlicesSection(HtmlPage& page, const OptimizeFigures& f) {
  if (f.slices.empty()) return;
  page.Heading(2, "Each objective against each parameter", "slices");
  page.Paragraph(
      "Slices through the search: every successful evaluation, one panel per searched parameter, with "
      "the candidates marked. A parameter whose panel shows a clear trend or a sharp edge matters for "
      "that objective; a flat cloud says the objective does not depend on it within its range.",
      "note");
  page.BeginDetails(
      fmt::format("{} figure{}, one per objective (click to open)", f.slices.size(), f.slices.size() == 1 ? "" : "s"));
  std::vector<HtmlPage::Figure> figures;
  for (const auto& s : f.slices) {
    figures.push_back(
        {s.png, s.label + " against each parameter", s.label + " against each parameter (" + s.file + ").", s.file});
  }
  page.FigureGrid(figures, 1);
  page.EndDetails();
}

// The search ranges, with the default and recommended values beside them.
void SearchRangesTable(HtmlPage& page, const optim::OptimizeResult& r) {
  const optim::Candidate* base = r.Find("default");
  const optim::Candidate* rec = r.Find("recommended");
  auto value_of = [](const optim::Candidate* c, const std::string& name) {
    if (c == nullptr) return std::string();
    const auto it = c->record.params.find(name);
    return it == c->record.params.end() ? std::string() : FormatParam(it->second);
  };
  std::vector<std::vector<std::string>> dims;
  for (const auto& d : r.space.dimensions) {
    const std::string symbol = ShortParamName(d.name);
    dims.push_back({symbol == d.name ? d.name : d.name + " (" + symbol + ")", FormatParam(d.lower),
                    FormatParam(d.upper), d.integer ? "int" : "real", value_of(base, d.name), value_of(rec, d.name)});
  }
  for (const auto& [name, value] : r.space.fixed) {
    dims.push_back({name, FormatParam(value), FormatParam(value), "fixed", value_of(base, name), value_of(rec, name)});
  }
  page.Table({"parameter", "lower", "upper", "type", "default", "recommended"}, dims);
}

// The run's settings as key/value rows, the search ranges, then the engine's settings collapsed.
void SettingsSection(HtmlPage& page, const optim::OptimizeResult& r) {
  page.Heading(2, "Settings");
  std::vector<std::pair<std::string, std::string>> settings, engine;
  if (r.settings.is_object()) {
    for (const auto& [key, value] : r.settings.items()) {
      if (key == "engine")
        FlattenSettings(value, "", engine);
      else if (key == "space")
        settings.push_back({key, "the parameter ranges below"});  // its fingerprint is for --resume
      else
        FlattenSettings(value, key, settings);
    }
  }
  if (!settings.empty()) page.KeyValues(settings);
  SearchRangesTable(page, r);
  if (!engine.empty()) {
    page.BeginDetails(
        fmt::format("Engine settings ({} values: base parameters, metric options, log identity)", engine.size()));
    page.KeyValues(engine);
    page.EndDetails();
  }
}

}  // namespace

std::string OptimizeHtml(const optim::OptimizeResult& r, const OptimizeFigures& f,
                         const std::optional<ErrorCorrelationSummary>& correlation,
                         const std::vector<std::string>& files) {
  const std::string log_name = std::filesystem::path(r.source.log_label).filename().string();
  HtmlPage page("slamtune optimize: " + log_name);
  page.Heading(1, "slamtune optimize: " + (log_name.empty() ? std::string("(no log named)") : log_name));
  FirstScreen(page, r, f);
  VerdictSection(page, r);
  RunSection(page, r);
  FrontEndSection(page, r, f);
  CandidatesSection(page, r, correlation.has_value());
  MapsSection(page, f);
  PopulationSection(page, f);
  HistorySection(page, r, f);
  SlicesSection(page, f);
  if (!f.parameter_space.empty()) {
    page.Heading(2, "Parameter space", "parameters");
    page.Image(f.parameter_space, "evaluated parameter sets in the search space",
               ParameterSpaceCaption(r) + " A recommendation at the edge of a range may lie beyond it.");
  }
  EvaluationsSection(page, r, correlation.has_value());
  if (correlation) CorrelationSection(page, f, *correlation);
  page.Heading(2, "What the objectives can tell");
  page.Paragraph(kObjectivesCaveat, "note");
  SettingsSection(page, r);
  page.Heading(2, "Files");
  page.List(files);
  return page.Finish();
}

}  // namespace slamtune::report
