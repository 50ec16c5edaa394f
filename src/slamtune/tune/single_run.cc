#include "slamtune/tune/single_run.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <filesystem>

#include "slamtune/common/atomic_file.h"
#include "slamtune/common/error.h"
#include "slamtune/common/output_dir.h"
#include "slamtune/io/map_image.h"
#include "slamtune/io/trajectory.h"
#include "slamtune/report/figures/front_end_map.h"
#include "slamtune/report/front_end_json.h"
#include "slamtune/report/png_encoding.h"
#include "slamtune/tune/run_files.h"

namespace slamtune::tune {
namespace {

std::string OutFile(const std::string& out, const char* name) { return (std::filesystem::path(out) / name).string(); }

// The inputs every command loads, the output folder checked before the log is read, and the
// base configuration with --no-loop-closure.
TuningInputs LoadRunInputs(const RunOptions& options) {
  TuningInputs input = LoadTuningInputs(options.inputs, options.quiet ? InputNotes::kDataLoss : InputNotes::kAll,
                                        [&options] { EnsureOutputDir(options.out); });
  if (options.no_loop_closure) input.base.do_loop_closing = false;
  input.base.Validate();
  return input;
}

// Progress every 50 scans.
optim::RunObservers ProgressEvery50Scans(Progress& progress) {
  optim::RunObservers observers;
  const auto start = std::chrono::steady_clock::now();
  observers.after_step = [&progress, start](const slam::LogRunner& runner) {
    const std::size_t done = runner.next_index(), total = runner.size();
    if (progress.quiet() || (done % 50 != 0 && done != total)) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress.Update(fmt::format("run: scan {}/{}, {} nodes, {} loops closed, {} elapsed", done, total,
                                runner.mapper().counters().scans_processed, runner.mapper().counters().loops_closed,
                                FormatDuration(elapsed)));
  };
  return observers;
}

// map.pgm/map.yaml and map.png; InputError when no reading lies within the range threshold.
void WriteMapFiles(const optim::SlamRun& run, const std::string& log_label, const std::string& out) {
  if (run.map.width <= 0 || run.map.height <= 0) {
    throw InputError(log_label, 0,
                     fmt::format("nothing to map: no reading of the {} processed scans lies within the range "
                                 "threshold ({} m); are all readings no-returns?",
                                 run.summary.nodes, run.range_threshold));
  }
  io::WriteMapServer(run.map, OutFile(out, "map.yaml"));
  io::WritePng(run.map, OutFile(out, "map.png"));
}

// trajectory.txt, loop_closures.csv, front_end.csv and front_end_map.png.
void WriteRunTables(const optim::SlamRun& run, const std::string& out) {
  io::WriteTrajectory(OutFile(out, "trajectory.txt"), run.trajectory);
  WriteLoopClosuresCsv(OutFile(out, "loop_closures.csv"), run.summary);
  WriteFrontEndCsv(OutFile(out, "front_end.csv"), run.sequential_matches, run.front_end);
  report::WriteBytes(
      report::EncodePng(report::RenderFrontEndMap(run.map, run.trajectory, run.sequential_matches, run.front_end)),
      OutFile(out, "front_end_map.png"));
}

}  // namespace

RunOutcome RunAndWrite(const RunOptions& options, Progress& progress) {
  const TuningInputs input = LoadRunInputs(options);
  TuningRunOptions single;
  single.no_share = true;  // one run: nothing to share
  const auto context = MakeEvaluationContext(input, {}, single);
  optim::RunObservers observers = ProgressEvery50Scans(progress);
  if (!options.trace.empty()) observers.trace = std::make_shared<slam::RunTrace>(options.trace);
  RunOutcome outcome;
  optim::SlamRun& run = outcome.run;
  optim::EvaluateSlam(*context, {}, &run, observers);
  if (observers.trace) observers.trace->Close();
  outcome.node_mode = input.base.node_mode;
  outcome.relations_label = input.source.relations_label;

  const auto write_start = std::chrono::steady_clock::now();
  WriteMapFiles(run, input.source.log_label, options.out);
  const double map_wall_s =
      run.map_wall_s + std::chrono::duration<double>(std::chrono::steady_clock::now() - write_start).count();
  WriteRunTables(run, options.out);
  nlohmann::json json = RunJson(run.summary, *input.log, input.source.log_label, input.base, run.quality, map_wall_s);
  json["lasers"] = LasersJson(run.lasers, run.summary);
  if (!input.source.relations_label.empty()) {
    outcome.error = run.error;
    json["gt_error"] = GtErrorJson(run.error, input.source.relations_label);
  }
  json["front_end"] = report::FrontEndEvidenceJson(run.front_end);
  json["peak_memory_mb"] = PeakMemoryMb();
  WriteFileAtomically(OutFile(options.out, "run.json"), json.dump(2) + "\n");
  return outcome;
}

std::string NodeRefusalsText(const slam::RunSummary& summary, slam::NodeMode mode) {
  if (summary.scans_refused_by_node_total() == 0) return "";
  std::string reasons;
  for (int v = 1; v < slam::kNumNodeVerdicts; ++v) {
    if (summary.scans_refused_by_node[v] == 0) continue;
    std::string name = slam::NameOf(static_cast<slam::NodeVerdict>(v));
    std::replace(name.begin(), name.end(), '_', ' ');
    reasons += fmt::format("{}{} {}", reasons.empty() ? "" : ", ", summary.scans_refused_by_node[v], name);
  }
  return fmt::format("; {} kept {} scans from Karto ({})", slam::LaunchOf(mode), summary.scans_refused_by_node_total(),
                     reasons);
}

std::string LasersText(const slam::LogLasers& lasers, const slam::RunSummary& summary) {
  if (lasers.geometries.size() < 2) return "";
  std::string text;
  for (std::size_t k = 0; k < lasers.geometries.size(); ++k) {
    text += fmt::format("{}{} ({} readings) {} nodes", text.empty() ? "" : ", ", lasers.names[k],
                        lasers.geometries[k]->num_readings, summary.nodes_per_laser[k]);
  }
  return "lasers: " + text + " (--beams per-geometry: one Karto laser per beam geometry, which the node does not do)";
}

std::string RelationErrorText(const std::optional<metrics::GtError>& e) {
  if (!e) return "";
  return fmt::format(", error {:.4f} +- {:.4f} m, {:.2f} +- {:.2f} deg ({} relations)", e->trans_mean_m, e->trans_std_m,
                     e->rot_mean_deg, e->rot_std_deg, e->relations_used);
}

}  // namespace slamtune::tune
