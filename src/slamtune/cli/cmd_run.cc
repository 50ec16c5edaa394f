// `slamtune run LOG --out DIR`: one Karto SLAM run on a CARMEN log (slam/log_runner.h) with
// the map (map.pgm + map.yaml as map_saver writes them, map.png), the trajectory of every log
// scan, the loop closures, and run.json (counts, timing, parameters, map metrics and, with
// --relations, the Freiburg relation error). The output folder is checked before the run and
// every file is written whole or not at all (atomic_file.h). Without LOG it runs on a built-in
// world simulated in memory (`--world`, `--world-seed`, as `optimize` does), and the world's
// relations give the error against its true trajectory unless --relations names others.
#include <fmt/format.h>
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/log_input.h"
#include "slamtune/cli/tuning_inputs.h"
#include "slamtune/common/atomic_file.h"
#include "slamtune/common/error.h"
#include "slamtune/common/output_dir.h"
#include "slamtune/common/progress.h"
#include "slamtune/io/log_reader.h"
#include "slamtune/io/log_summary.h"
#include "slamtune/io/map_image.h"
#include "slamtune/io/relations.h"
#include "slamtune/io/trajectory.h"
#include "slamtune/metrics/gt_error.h"
#include "slamtune/metrics/map_quality.h"
#include "slamtune/metrics/relation_match.h"
#include "slamtune/report/front_end_json.h"
#include "slamtune/report/front_end_map.h"
#include "slamtune/report/png_encoding.h"
#include "slamtune/report/scan_losses_json.h"
#include "slamtune/sim/simulation.h"
#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/mapper_params.h"
#include "slamtune/slam/occupancy_grid.h"
#include "slamtune/slam/params_yaml.h"
#include "slamtune/slam/run_trace.h"

namespace slamtune::cli {
namespace {

struct RunArgs {
  std::string log;
  std::string out;
  std::string params_file;
  std::string preset;  // "" = slam_karto, or the node of --params in its default mode
  std::vector<std::string> sets;
  std::string relations;
  std::string world = sim::kDefaultWorld;  // simulated when no LOG is given
  unsigned world_seed = 1;
  bool no_loop_closure = false;
  std::string trace;  // --trace FILE: every match and solve (slam/run_trace.h)
  LogInputOptions input;
  bool quiet = false;
};

nlohmann::json FiniteOrNull(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json ParamsJson(const slam::MapperParams& params) {
  nlohmann::json out = nlohmann::json::object();
  for (const slam::NamedParam& p : slam::ToNamedValues(params)) {
    std::visit([&](const auto& v) { out[p.name] = v; }, p.value);
  }
  return out;
}

double PeakMemoryMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

void WriteLoopClosuresCsv(const std::string& path, const slam::RunSummary& s) {
  std::string csv =
      "log_index,node,chain_first,chain_last,linked_to,coarse_response,fine_response,coarse_var_xx,"
      "coarse_var_xy,coarse_var_yy\n";
  for (const slam::LoopClosureRecord& l : s.loop_closures) {
    csv += fmt::format("{},{},{},{},{},{:.9g},{:.9g},{:.9g},{:.9g},{:.9g}\n", l.log_index, l.node, l.chain_first,
                       l.chain_last, l.linked_to, l.coarse_response, l.fine_response, l.coarse_var_xx, l.coarse_var_xy,
                       l.coarse_var_yy);
  }
  WriteFileAtomically(path, csv);
}

// One row per sequential match (slam/front_end_evidence.h), `suspect` by the run's median response.
void WriteFrontEndCsv(const std::string& path, const std::vector<slam::SequentialMatchStep>& steps,
                      const slam::FrontEndEvidence& evidence) {
  std::string csv =
      "log_index,time,response,dx,dy,x,y,dtheta,sigma_xy,sigma_minor,at_window_edge,at_heading_edge,suspect,"
      "degenerate\n";
  for (const slam::SequentialMatchStep& s : steps) {
    csv += fmt::format("{},{:.6f},{:.6g},{:.6g},{:.6g},{:.4f},{:.4f},{:.6g},{:.6g},{:.6g},{},{},{},{}\n", s.log_index,
                       s.time, s.response, s.dx, s.dy, s.x, s.y, s.dtheta, s.sigma_xy, s.sigma_minor,
                       s.at_window_edge ? 1 : 0, s.at_heading_edge ? 1 : 0,
                       slam::IsSuspect(s, evidence.median_response, {}) ? 1 : 0, slam::IsDegenerate(s, {}) ? 1 : 0);
  }
  WriteFileAtomically(path, csv);
}

// The base configuration every command loads (slam/base_configuration.h), with --no-loop-closure.
slam::MapperParams ResolveParams(const RunArgs& args) {
  const slam::BaseConfiguration base = slam::LoadBaseConfiguration(args.params_file, args.preset, args.sets);
  PrintParamsWarnings(base);
  if (!args.quiet) {
    std::fprintf(stderr, "base: %s, modelling %s (mode: %s)\n", base.label.c_str(),
                 slam::LaunchOf(base.params.node_mode), base.mode_source.c_str());
  }
  slam::MapperParams params = base.params;
  if (args.no_loop_closure) params.do_loop_closing = false;
  params.Validate();
  return params;
}

std::string OutFile(const std::string& out, const char* name) { return (std::filesystem::path(out) / name).string(); }

// The log a run works on and the relations its error is measured against.
struct RunInput {
  std::shared_ptr<const io::LaserLog> log;
  std::vector<io::Relation> relations;  // --relations, or the simulated world's own
  std::string log_label;                // the path, or "built-in world NAME (seed N)"
  std::string relations_label;          // the path, "simulated (true trajectory)", or empty
};

// Reads the log, or simulates `world` without one (whose relations stand in for missing
// --relations); says what was read, and checks that the relations match scans of the log.
void LoadRunLog(const RunArgs& args, const sim::SimulationOptions& world, RunInput& input) {
  input.log_label = args.log;
  input.relations_label = args.relations;
  if (args.log.empty()) {
    if (!args.quiet) {
      std::fprintf(stderr, "no LOG given: simulating the built-in world '%s' (seed %u)\n", args.world.c_str(),
                   args.world_seed);
    }
    sim::Simulation simulation = sim::Simulate(world);
    input.log = std::make_shared<const io::LaserLog>(std::move(simulation.log));
    input.log_label = fmt::format("built-in world {} (seed {})", args.world, args.world_seed);
    if (args.relations.empty()) {
      input.relations = std::move(simulation.relations);
      input.relations_label = "simulated (true trajectory)";
    }
  } else {
    input.log = std::make_shared<const io::LaserLog>(ReadLog(args.log, args.input));
  }
  PrintLogInput(*input.log, args.quiet);
  io::RequireRanges(*input.log);
  if (!args.relations.empty()) {
    const metrics::RelationMatch match = metrics::RequireMatchingRelations(*input.log, input.relations, args.relations);
    if (!args.quiet && !match.complete()) WarnPartialRelations(args.relations, match);
  }
}

// The SLAM run over the whole log, with progress every 50 scans and, with --trace, every match
// and solve written to the trace file.
void RunSlam(const RunArgs& args, slam::LogRunner& runner, Progress& progress) {
  std::shared_ptr<slam::RunTrace> trace;
  if (!args.trace.empty()) {
    trace = std::make_shared<slam::RunTrace>(args.trace);
    runner.set_trace(trace);
  }
  const auto start = std::chrono::steady_clock::now();
  runner.RunToEnd([&](std::size_t done, std::size_t total) {
    if (progress.quiet() || (done % 50 != 0 && done != total)) return;
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    progress.Update(fmt::format("run: scan {}/{}, {} nodes, {} loops closed, {} elapsed", done, total,
                                runner.mapper().counters().scans_processed, runner.mapper().counters().loops_closed,
                                FormatDuration(elapsed)));
  });
  if (trace) trace->Close();
}

// The map of the final poses (§8) and its metrics.
struct RunMap {
  io::MapImage image;
  metrics::MapQuality quality;
  double wall_s = 0;  // building, writing and measuring it
};

// Builds the map, writes map.pgm/map.yaml and map.png, and measures it. InputError when no
// reading lies within the range threshold (nothing to map).
RunMap WriteMap(const slam::LogRunner& runner, const slam::MapperParams& params, const std::string& log_label,
                const std::string& out) {
  const auto map_start = std::chrono::steady_clock::now();
  RunMap map;
  map.image = slam::OccupancyGrid::FromScans(std::span<const slam::LaserScan>(runner.mapper().scans()),
                                             slam::GridOptionsOf(params))
                  .ToMapImage();
  if (map.image.width <= 0 || map.image.height <= 0) {
    throw InputError(log_label, 0,
                     fmt::format("nothing to map: no reading of the {} processed scans lies within the range "
                                 "threshold ({} m); are all readings no-returns?",
                                 runner.mapper().scans().size(), runner.mapper().range_threshold()));
  }
  io::WriteMapServer(map.image, OutFile(out, "map.yaml"));
  io::WritePng(map.image, OutFile(out, "map.png"));
  map.quality = metrics::ComputeMapQuality(map.image);
  map.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - map_start).count();
  return map;
}

// trajectory.txt, loop_closures.csv, front_end.csv and front_end_map.png; returns where the
// front end may have lost its place.
slam::FrontEndEvidence WriteRunTables(const slam::LogRunner& runner, const slam::RunSummary& summary,
                                      const std::vector<io::TimedPose>& trajectory, const io::MapImage& map,
                                      const std::string& out) {
  io::WriteTrajectory(OutFile(out, "trajectory.txt"), trajectory);
  WriteLoopClosuresCsv(OutFile(out, "loop_closures.csv"), summary);
  const slam::FrontEndEvidence front_end = slam::AssessFrontEnd(runner.sequential_matches());
  WriteFrontEndCsv(OutFile(out, "front_end.csv"), runner.sequential_matches(), front_end);
  report::WriteBytes(
      report::EncodePng(report::RenderFrontEndMap(map, trajectory, runner.sequential_matches(), front_end)),
      OutFile(out, "front_end_map.png"));
  return front_end;
}

nlohmann::json MapJson(const metrics::MapQuality& quality) {
  return {{"width", quality.width},
          {"height", quality.height},
          {"resolution", quality.resolution},
          {"occupied_cells", quality.occupied_cells},
          {"free_cells", quality.free_cells},
          {"unknown_cells", quality.unknown_cells},
          {"occupied_ratio", quality.occupied_ratio},
          {"corner_pixels", quality.corner_pixels},
          {"corners", quality.corners},
          {"enclosed_areas", quality.enclosed_areas},
          {"message", quality.message}};
}

// "; slam_toolbox online_sync_launch.py (synchronous node) kept 120 scans from Karto (100 not
// moved, 16 too soon, 4 warming up)", or "" when the node handed every scan on.
std::string RefusedByNodeText(const slam::RunSummary& summary, slam::NodeMode mode) {
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

// run.json's "lasers": the run's Karto lasers (one, or one per beam geometry with --beams
// per-geometry, docs/engine.md §3.5) and the nodes of each.
nlohmann::json LasersJson(const slam::LogLasers& lasers, const slam::RunSummary& summary) {
  nlohmann::json out = nlohmann::json::array();
  for (std::size_t k = 0; k < lasers.geometries.size(); ++k) {
    const slam::LaserGeometry& g = *lasers.geometries[k];
    out.push_back({{"name", lasers.names[k]},
                   {"readings", g.num_readings},
                   {"first_angle_rad", g.min_angle},
                   {"angle_increment_rad", g.angular_resolution},
                   {"nodes", summary.nodes_per_laser[k]}});
  }
  return out;
}

// "lasers: laser_0 (180 readings) 2412 nodes, laser_1 (179 readings) 1207 nodes ...", or "" with one laser.
std::string LasersText(const slam::LogLasers& lasers, const slam::RunSummary& summary) {
  if (lasers.geometries.size() < 2) return "";
  std::string text;
  for (std::size_t k = 0; k < lasers.geometries.size(); ++k) {
    text += fmt::format("{}{} ({} readings) {} nodes", text.empty() ? "" : ", ", lasers.names[k],
                        lasers.geometries[k]->num_readings, summary.nodes_per_laser[k]);
  }
  return "lasers: " + text + " (--beams per-geometry: one Karto laser per beam geometry, which the node does not do)";
}

// run.json's counts, timing, laser, input, parameters and map metrics.
nlohmann::json RunJson(const slam::RunSummary& summary, const io::LaserLog& log, const std::string& log_label,
                       const slam::MapperParams& params, const RunMap& map) {
  nlohmann::json edges = nlohmann::json::object(), duplicates = nlohmann::json::object();
  for (int k = 0; k < slam::kNumEdgeKinds; ++k) {
    edges[slam::EdgeKindName(static_cast<slam::EdgeKind>(k))] = summary.edges[k];
    duplicates[slam::EdgeKindName(static_cast<slam::EdgeKind>(k))] = summary.duplicate_edges[k];
  }
  return {
      {"log", log_label},
      {"scans", summary.scans_read},
      {"node_mode", slam::NameOf(params.node_mode)},
      {"scans_offered", summary.scans_offered},
      {"scans_not_used", report::ScanLossesJson(slam::RunLosses(log, summary, params.node_mode))},
      {"nodes", summary.nodes},
      {"loop_closures", summary.loop_closures.size()},
      {"loop_attempts", summary.loop_attempts},
      {"near_chain_matches", summary.near_chain_matches},
      {"near_chain_matches_skipped", summary.near_chain_matches_skipped},
      {"edges", edges},
      {"duplicate_edges", duplicates},
      {"solver_runs", summary.solver_runs},
      {"solver_wall_s", summary.solver_wall_s},
      {"wall_s", summary.wall_s},
      {"map_wall_s", map.wall_s},
      {"log_duration_s", summary.log_duration_s},
      {"realtime_factor", summary.wall_s > 0 ? FiniteOrNull(summary.log_duration_s / summary.wall_s) : nullptr},
      {"laser_max_range_m", summary.laser_max_range},
      {"range_threshold_m", summary.range_threshold},
      {"no_return_value_m", FiniteOrNull(log.no_return_value)},
      {"no_return_rule", log.no_return_rule},
      {"input", io::DescribeLogInput(log)},
      {"params", ParamsJson(params)},
      {"map", MapJson(map.quality)},
  };
}

// With relations: their error in run.json ("gt_error") and the summary's ", error ..." part.
std::string AddGtError(const std::vector<io::TimedPose>& trajectory, const RunInput& input, nlohmann::json& run) {
  if (input.relations_label.empty()) return "";
  const metrics::GtError e = metrics::ComputeGtError(trajectory, input.relations);
  nlohmann::json gt = nlohmann::json::object();
  for (const auto& [key, value] : metrics::GtErrorFields(e)) gt[key] = FiniteOrNull(value);
  gt["relations_used"] = e.relations_used;
  gt["relations_missing"] = e.relations_missing;
  gt["relations_file"] = input.relations_label;
  run["gt_error"] = gt;
  return fmt::format(", error {:.4f} +- {:.4f} m, {:.2f} +- {:.2f} deg ({} relations)", e.trans_mean_m, e.trans_std_m,
                     e.rot_mean_deg, e.rot_std_deg, e.relations_used);
}

void PrintRunSummary(const slam::RunSummary& summary, slam::NodeMode mode, const std::string& gt_line,
                     const std::string& out, const slam::FrontEndEvidence& front_end) {
  const std::string dropped = summary.scans_wrong_reading_count > 0
                                  ? fmt::format(", {} scans dropped (reading count differs from the first scan's)",
                                                summary.scans_wrong_reading_count)
                                  : "";
  std::printf("run: %d scans, %d nodes, %zu loop closures, %d edges, %.1f s wall%s%s%s; wrote %s\n", summary.scans_read,
              summary.nodes, summary.loop_closures.size(), summary.total_edges(), summary.wall_s,
              RefusedByNodeText(summary, mode).c_str(), dropped.c_str(), gt_line.c_str(), out.c_str());
  std::printf("%s\n", front_end.Summary().c_str());
  if (front_end.points_at_front_end()) {
    std::printf(
        "  (front_end_map.png marks them on the map, front_end.csv has every match; the default "
        "optimize searches the front-end parameters for this log)\n");
  }
}

int Run(const RunArgs& args) {
  if (args.log.empty()) args.input.RequireLogForSlice(args.world);  // before anything is said or written
  const slam::MapperParams params = ResolveParams(args);
  RunInput input;
  if (!args.relations.empty()) input.relations = io::ReadRelations(args.relations);  // fail before the long run
  sim::SimulationOptions world;
  world.world = args.world;
  world.seed = args.world_seed;
  if (args.log.empty()) world.Validate();
  EnsureOutputDir(args.out);

  Progress progress(args.quiet ? Progress::Mode::kQuiet : Progress::Mode::kAuto, 10.0);
  LoadRunLog(args, world, input);
  slam::LogRunner runner(input.log, params);
  RunSlam(args, runner, progress);
  const slam::RunSummary summary = runner.Summary();
  const std::vector<io::TimedPose> trajectory = runner.Trajectory();

  const RunMap map = WriteMap(runner, params, input.log_label, args.out);
  const slam::FrontEndEvidence front_end = WriteRunTables(runner, summary, trajectory, map.image, args.out);
  nlohmann::json run = RunJson(summary, *input.log, input.log_label, params, map);
  run["lasers"] = LasersJson(runner.lasers(), summary);
  const std::string gt_line = AddGtError(trajectory, input, run);
  run["front_end"] = report::FrontEndEvidenceJson(front_end);
  run["peak_memory_mb"] = PeakMemoryMb();
  WriteFileAtomically(OutFile(args.out, "run.json"), run.dump(2) + "\n");

  progress.Finish();
  PrintRunSummary(summary, params.node_mode, gt_line, args.out, front_end);
  const std::string lasers = LasersText(runner.lasers(), summary);
  if (!lasers.empty()) std::printf("%s\n", lasers.c_str());
  return 0;
}

const SubcommandRegistrar kRun(Subcommand{
    "run",
    "Run the Karto-faithful SLAM engine on a log or bag: map.pgm/map.yaml/map.png, trajectory.txt, "
    "loop_closures.csv, front_end.csv, front_end_map.png and run.json in --out",
    20, [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<RunArgs>();
      app.add_option("LOG", args->log,
                     "CARMEN log (plain or gzip), or a ROS 2 / ROS 1 bag; none: the built-in world --world");
      app.add_option("--out", args->out, "Output folder (created)")->required();
      app.add_option("--params", args->params_file,
                     "your slam_toolbox (ROS 2) or slam_karto (flat) parameter file, or a best.yaml that optimize "
                     "wrote; keys it does not set take that node's own defaults");
      AddPresetOption(app, args->preset);
      app.add_option("--set", args->sets, "Override one parameter, name=value (repeatable; applied last)");
      app.add_option("--relations", args->relations, "Freiburg relations file: report the relation error");
      app.add_option("--world", args->world, "built-in world to simulate when no LOG is given (see `simulate --list`)")
          ->capture_default_str();
      app.add_option("--world-seed", args->world_seed, "seed of the simulated world")->capture_default_str();
      app.add_flag("--no-loop-closure", args->no_loop_closure, "Same as --set do_loop_closing=false");
      app.add_option("--trace", args->trace,
                     "Write every scan match and back-end solve to FILE at full precision (docs/trace.md)");
      args->input.AddTo(app);
      app.add_flag("--quiet", args->quiet, "No progress on stderr");
      app.footer(
          "Examples:\n"
          "  slamtune run drive.mcap --out runs/drive_defaults\n"
          "  slamtune run drive.mcap --out runs/drive_best --params runs/drive/best.yaml\n"
          "  slamtune run intel.clf.gz --relations intel.relations --set loop_search_maximum_distance=6 --out "
          "runs/intel_r6\n"
          "  slamtune run --world corridor-long --out runs/corridor   # a built-in world, error against its truth");
      return [args]() -> int { return Run(*args); };
    }});

}  // namespace
}  // namespace slamtune::cli
