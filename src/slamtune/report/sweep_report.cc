// The sweep outputs (sweep_report.h).
#include "slamtune/report/sweep_report.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <functional>

#include "slamtune/common/error.h"
#include "slamtune/io/log_summary.h"
#include "slamtune/report/html_page.h"
#include "slamtune/report/optimize_html.h"
#include "slamtune/report/optimize_tables.h"
#include "slamtune/report/png_encoding.h"
#include "slamtune/report/report_text.h"
#include "slamtune/report/tables.h"

namespace slamtune::report {
namespace {

namespace fs = std::filesystem;

std::string Title(optim::Objective objective) { return optim::InfoOf(objective).title; }

double Unbacked(const optim::EvaluationRecord& r) { return optim::ValueOf(r, optim::Objective("unbacked_hits")); }

CsvTable SweepTable(const std::string& parameter, const std::vector<SweepPoint>& points, bool gt) {
  CsvTable t;
  t.header = {"parameter", "value", "status", "reason", "loop_closures"};
  for (const optim::RecordFigure& figure : optim::RecordFigures()) t.header.push_back(figure.key);
  t.header.insert(t.header.end(), {"nodes", "wall_s"});
  if (gt)
    t.header.insert(t.header.end(), {"trans_mean_m", "trans_std_m", "rot_mean_deg", "rot_std_deg", "relations_used"});
  t.header.push_back("loop_scans");
  for (const auto& p : points) {
    const auto& r = p.record;
    std::vector<std::string> row = {parameter, FormatNumber(p.value), NameOf(r.status), r.reason,
                                    r.ok() ? std::to_string(r.loop_closures) : ""};
    for (const optim::RecordFigure& figure : optim::RecordFigures())
      row.push_back(FigureCell(r, optim::FigureValue(figure, r)));
    row.insert(row.end(), {r.ok() ? std::to_string(r.nodes) : "", FormatNumber(r.wall_s)});
    if (gt) {
      const bool has = r.ok() && r.has_gt;
      row.insert(row.end(), {has ? FormatNumber(r.trans_mean_m) : "", has ? FormatNumber(r.trans_std_m) : "",
                             has ? FormatNumber(r.rot_mean_deg) : "", has ? FormatNumber(r.rot_std_deg) : "",
                             has ? std::to_string(r.relations_used) : ""});
    }
    row.push_back(JoinScans(r.loop_scans));
    t.AddRow(std::move(row));
  }
  return t;
}

struct Quantity {
  std::string title;  // panel title and y label
  std::function<double(const optim::EvaluationRecord&)> get;
  bool needs_gt;
};

Quantity ObjectiveQuantity(optim::Objective objective) {
  return {Title(objective), [objective](const optim::EvaluationRecord& r) { return optim::ValueOf(r, objective); },
          false};
}

cv::Mat SweepFigure(const std::string& parameter, const std::vector<SweepPoint>& points, bool gt,
                    const SweepReportOptions& options) {
  const std::vector<Quantity> quantities = {
      {"loop closures", [](const optim::EvaluationRecord& r) { return static_cast<double>(r.loop_closures); }, false},
      ObjectiveQuantity(optim::Objective("unbacked_hits")),
      ObjectiveQuantity(optim::Objective("occupied_ratio")),
      ObjectiveQuantity(optim::Objective("corner_pixels")),
      ObjectiveQuantity(optim::Objective("enclosed_areas")),
      {"mean translational error (m)", [](const optim::EvaluationRecord& r) { return r.trans_mean_m; }, true},
      {"mean rotational error (deg)", [](const optim::EvaluationRecord& r) { return r.rot_mean_deg; }, true},
  };
  const std::string x_label =
      parameter + (ShortParamName(parameter) != parameter ? " (" + ShortParamName(parameter) + ")" : "");
  std::vector<cv::Mat> panels;
  for (std::size_t k = 0; k < quantities.size(); ++k) {
    const Quantity& q = quantities[k];
    if (q.needs_gt && !gt) continue;
    Series s = MakeSeries("", {}, {}, SeriesStyle::kLineAndMarkers);
    s.colour = PaletteColour(k == 0 ? 1 : 0);
    for (const auto& p : points) {
      if (!p.record.ok() || (q.needs_gt && !p.record.has_gt)) continue;
      s.x.push_back(p.value);
      s.y.push_back(q.get(p.record));
    }
    PlotOptions o = options.panel.Plot();
    o.title = q.title;
    o.x_label = x_label;
    o.y_label = q.title;
    o.legend = false;
    panels.push_back(RenderPlot({s}, o).image);
  }
  GridOptions g;
  g.columns = 3;
  const int failed =
      static_cast<int>(std::count_if(points.begin(), points.end(), [](const SweepPoint& p) { return !p.record.ok(); }));
  g.title = fmt::format("Sweep of {}{}", parameter,
                        failed ? fmt::format(" ({} failed run{} not shown)", failed, failed == 1 ? "" : "s") : "");
  return ComposeGrid(panels, g);
}

void WriteFile(const std::string& text, const fs::path& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path.string(), 0, "cannot write the file (missing folder or no permission?)");
  out << text;
  out.close();
  if (!out) throw InputError(path.string(), 0, "writing the file failed (disk full?)");
}

std::string SweepHtml(const std::string& parameter, const std::vector<SweepPoint>& points, bool gt,
                      const std::vector<std::uint8_t>& png, const SweepReportOptions& options) {
  HtmlPage page("slamtune sweep: " + parameter);
  page.Heading(1, "slamtune sweep: " + parameter);
  std::vector<std::pair<std::string, std::string>> run = {
      {"log", options.log_path.empty() ? "(not given)" : options.log_path},
      {"varied", parameter},
      {"points", std::to_string(points.size())}};
  for (const auto& row : io::InputRows(options.log_input)) run.push_back(row);
  std::string held;
  for (const auto& [name, value] : points.front().record.params) {
    if (name == parameter) continue;
    held += (held.empty() ? "" : ", ") + ShortParamName(name) + " = " + FormatParam(value);
  }
  run.push_back({"held (from the first point)", held.empty() ? "(none recorded)" : held});
  page.KeyValues(run);
  page.Image(png, "loop closures and objectives against " + parameter, "sweep.png");
  std::vector<std::string> header = {ShortParamName(parameter), "status", "loop closures", "u_h", "eta", "n_c", "n_e"};
  if (gt) header.insert(header.end(), {"trans. error (m)", "rot. error (deg)"});
  std::vector<std::vector<std::string>> rows;
  for (const auto& p : points) {
    const auto& r = p.record;
    std::vector<std::string> row = {FormatParam(p.value), r.ok() ? "ok" : "failed: " + r.reason};
    if (r.ok()) {
      row.insert(row.end(), {std::to_string(r.loop_closures), fmt::format("{:.4g}", Unbacked(r)),
                             fmt::format("{:.5g}", r.occupied_ratio), fmt::format("{:.5g}", r.corner_pixels),
                             fmt::format("{:.5g}", r.enclosed_areas)});
    } else {
      row.insert(row.end(), {"", "", "", "", ""});
    }
    if (gt) {
      const bool has = r.ok() && r.has_gt;
      row.push_back(has ? FormatMeanStd(r.trans_mean_m, r.trans_std_m) : "");
      row.push_back(has ? FormatMeanStd(r.rot_mean_deg, r.rot_std_deg) : "");
    }
    rows.push_back(std::move(row));
  }
  page.Table(header, rows);
  page.Paragraph(kObjectivesCaveat, "note");
  page.List({"sweep.csv", "sweep.png", "sweep.html"});
  return page.Finish();
}

}  // namespace

void SweepReportOptions::Validate() const { panel.Validate("SweepReportOptions.panel"); }

SweepReportSummary WriteSweepReport(const std::string& parameter, const std::vector<SweepPoint>& points,
                                    const std::string& dir, const SweepReportOptions& options) {
  // Validate everything before touching the disk.
  options.Validate();
  if (parameter.empty()) throw InputError("sweep: the varied parameter's name is empty");
  if (points.empty()) throw InputError("sweep of " + parameter + ": no points to report");
  for (const auto& p : points) {
    if (!std::isfinite(p.value)) {
      throw InputError(fmt::format("sweep of {}: value {} is not finite", parameter, p.value));
    }
  }
  std::vector<SweepPoint> sorted = points;
  std::stable_sort(sorted.begin(), sorted.end(),
                   [](const SweepPoint& a, const SweepPoint& b) { return a.value < b.value; });

  SweepReportSummary summary;
  summary.dir = dir;
  summary.points = static_cast<int>(sorted.size());
  for (const auto& p : sorted) {
    summary.failed += p.record.ok() ? 0 : 1;
    summary.with_ground_truth = summary.with_ground_truth || p.record.has_gt;
  }
  std::error_code ec;
  fs::create_directories(dir, ec);
  if (ec || !fs::is_directory(dir)) {
    throw InputError(dir, 0, "cannot create the sweep folder: " + (ec ? ec.message() : "not a directory"));
  }
  const bool gt = summary.with_ground_truth;
  WriteCsv(SweepTable(parameter, sorted, gt), (fs::path(dir) / "sweep.csv").string());
  const std::vector<std::uint8_t> png = EncodePng(SweepFigure(parameter, sorted, gt, options));
  WriteBytes(png, (fs::path(dir) / "sweep.png").string());
  WriteFile(SweepHtml(parameter, sorted, gt, png, options), fs::path(dir) / "sweep.html");
  summary.files = {"sweep.csv", "sweep.png", "sweep.html"};
  return summary;
}

}  // namespace slamtune::report
