// The optimisation report folder (optimize_report.h).
#include "slamtune/report/optimize_report.h"

#include <fmt/format.h>

#include <cctype>
#include <filesystem>
#include <fstream>

#include "slamtune/common/error.h"
#include "slamtune/io/map_image.h"
#include "slamtune/report/figures/front_end_map.h"
#include "slamtune/report/figures/map_panels.h"
#include "slamtune/report/figures/optimize_figures.h"
#include "slamtune/report/optimize_html.h"
#include "slamtune/report/optimize_tables.h"
#include "slamtune/report/png_encoding.h"
#include "slamtune/report/report_text.h"
#include "slamtune/report/results_json.h"

namespace slamtune::report {
namespace {

namespace fs = std::filesystem;

// Labels become file names: keep letters, digits, '-' and '_'.
std::string FileSafe(const std::string& label) {
  std::string out;
  for (char c : label) out += (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_') ? c : '_';
  return out.empty() ? "unnamed" : out;
}

void WriteText(const std::string& text, const std::string& path) {
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  if (!out) throw InputError(path, 0, "cannot write the file (missing folder or no permission?)");
  out << text;
  out.close();
  if (!out) throw InputError(path, 0, "writing the file failed (disk full?)");
}

class FolderWriter {
 public:
  explicit FolderWriter(const std::string& dir) : dir_(dir) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec || !fs::is_directory(dir)) {
      throw InputError(dir, 0, "cannot create the report folder: " + (ec ? ec.message() : "not a directory"));
    }
  }
  std::string Path(const std::string& name) const { return (fs::path(dir_) / name).string(); }
  void Csv(const CsvTable& table, const std::string& name) {
    WriteCsv(table, Path(name));
    files_.push_back(name);
  }
  std::vector<std::uint8_t> Png(const cv::Mat& image, const std::string& name) {
    std::vector<std::uint8_t> png = EncodePng(image);
    WriteBytes(png, Path(name));
    files_.push_back(name);
    return png;
  }
  void Text(const std::string& text, const std::string& name) {
    WriteText(text, Path(name));
    files_.push_back(name);
  }
  void Record(const std::string& name) { files_.push_back(name); }
  const std::vector<std::string>& files() const { return files_; }

 private:
  std::string dir_;
  std::vector<std::string> files_;
};

// "recommended = knee: r=3.2 g=12, 5 loop closures; u_h 0.0123, n_c 912, n_e 14."
std::string MapCaption(const CandidateGroup& group, const optim::OptimizeResult& result) {
  const optim::Candidate& c = group.shown();
  std::string text = group.label + ": " + ParamSummary(c.record.params, result.space);
  if (c.record.status != optim::RunStatus::kOk) return text + ", run failed: " + c.record.reason;
  text += fmt::format(", {} loop closure{}", c.record.loop_closures, c.record.loop_closures == 1 ? "" : "s");
  const std::vector<double> values = result.objectives.Values(c.record);
  for (std::size_t k = 0; k < values.size(); ++k) {
    text += fmt::format("{} {} {}", k == 0 ? "; " : ", ", ObjectiveAt(result, k).short_name, Readable(values[k], 4));
  }
  if (c.record.has_gt) text += ", error " + Metres(c.record.trans_mean_m) + " m";
  if (!HasMap(c.map)) text += " (no map rendered)";
  return text + ".";
}

// The seed paper's tables and every evaluation, as CSV.
void WriteTables(const optim::OptimizeResult& result, bool gt, FolderWriter& out) {
  out.Csv(ParamsTable(result), "table3_best_worst_params.csv");
  out.Csv(ObjectivesTable(result), "table4_6_objectives.csv");
  out.Csv(LoopClosuresTable(result), "table7_loop_closures.csv");
  out.Csv(LoopScansTable(result), "table8_loop_scans.csv");
  if (gt) out.Csv(ErrorsTable(result), "table9_10_errors.csv");
  out.Csv(EvaluationsTable(result.evaluations, result.space), "evaluations.csv");
}

// The candidates' maps: side by side, one panel per group of candidates that share a map, and each
// map as map_server files. Returns how many maps were written as map_server files.
int WriteCandidateMaps(const optim::OptimizeResult& result, const FigureOptions& options, FolderWriter& out,
                       OptimizeFigures& figures) {
  int maps_written = 0;
  if (result.candidates.empty()) return maps_written;
  figures.maps = out.Png(MapsSideBySide(result, options), "maps_side_by_side.png");
  for (const CandidateMapPanel& panel : CandidateMapPanels(result, options)) {
    std::string labels;
    for (const auto* c : panel.group.members) {
      if (!labels.empty()) labels += '_';
      labels += FileSafe(c->label);
    }
    const std::string file = "map_" + labels + ".png";
    figures.map_panels.push_back(
        {panel.group.label, file, out.Png(panel.image, file), MapCaption(panel.group, result)});
  }
  for (const auto* c : CandidatesInReportOrder(result)) {
    if (!HasMap(c->map)) continue;
    const std::string stem = "map_" + FileSafe(c->label);
    io::WriteMapServer(c->map, out.Path(stem + ".yaml"));
    out.Record(stem + ".pgm");
    out.Record(stem + ".yaml");
    ++maps_written;
  }
  return maps_written;
}

}  // namespace

OptimizeReportSummary WriteOptimizeReport(const optim::OptimizeResult& result, const std::string& dir,
                                          const FigureOptions& options) {
  options.Validate();  // before touching the disk
  OptimizeReportSummary summary;
  summary.dir = dir;
  FolderWriter out(dir);
  const bool gt = HasGroundTruth(result);

  std::vector<optim::EvaluationRecord> gt_runs;
  if (gt) {
    gt_runs = GroundTruthRuns(result.evaluations);
    summary.correlation = CorrelateObjectivesWithError(result.evaluations, result.objectives.objectives());
  }
  out.Text(ResultsJson(result, summary.correlation).dump(2) + "\n", "results.json");

  WriteTables(result, gt, out);

  OptimizeFigures figures;
  summary.maps_written = WriteCandidateMaps(result, options, out, figures);
  for (const auto& snapshot : result.snapshots) {
    const std::string name = fmt::format("population_gen{}.png", snapshot.generation);
    figures.populations.emplace_back(snapshot.generation, out.Png(PopulationFigure(snapshot, result, options), name));
  }
  if (!result.snapshots.empty()) {
    figures.evolution = out.Png(PopulationEvolutionFigure(result, options), "population_evolution.png");
  }
  for (std::size_t k = 0; k < result.objectives.size(); ++k) {
    const cv::Mat slices = ObjectiveAgainstParameters(result, k, options);
    if (slices.empty()) continue;
    const std::string name = std::string("slices_") + optim::InfoOf(result.objectives.objectives()[k]).key + ".png";
    figures.slices.push_back({ObjectiveAt(result, k).short_name, name, out.Png(slices, name), ""});
  }
  if (const cv::Mat history = HistoryFigure(result, options); !history.empty()) {
    figures.history = out.Png(history, "history.png");
  }
  if (const cv::Mat space = ParameterSpaceFigure(result, options); !space.empty()) {
    figures.parameter_space = out.Png(space, "parameter_space.png");
  }
  if (gt) {
    figures.objective_vs_error =
        out.Png(ObjectiveVsErrorFigure(gt_runs, *summary.correlation, result, options), "objective_vs_error.png");
  }

  if (result.base_front_end) {
    const optim::BaseFrontEnd& fe = *result.base_front_end;
    figures.front_end = out.Png(FrontEndFigure(fe, options), "front_end.png");
    if (HasMap(fe.map)) {
      figures.front_end_map =
          out.Png(RenderFrontEndMap(fe.map, fe.trajectory, fe.steps, fe.evidence), "front_end_map.png");
    }
  }

  std::vector<std::string> listed = out.files();
  listed.push_back("report.html");
  out.Text(OptimizeHtml(result, figures, summary.correlation, listed), "report.html");
  summary.files = out.files();
  return summary;
}

}  // namespace slamtune::report
