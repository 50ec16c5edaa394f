#include "slamtune/tune/run_files.h"

#include <fmt/format.h>
#include <sys/resource.h>

#include "slamtune/common/atomic_file.h"
#include "slamtune/io/log_summary.h"
#include "slamtune/report/json_number.h"
#include "slamtune/report/scan_losses_json.h"
#include "slamtune/slam/params/params_yaml.h"
#include "slamtune/slam/pose_graph.h"

namespace slamtune::tune {

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

nlohmann::json ParamsJson(const slam::MapperParams& params) {
  nlohmann::json out = nlohmann::json::object();
  for (const slam::NamedParam& p : slam::ToNamedValues(params)) {
    std::visit([&](const auto& v) { out[p.name] = v; }, p.value);
  }
  return out;
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

nlohmann::json GtErrorJson(const metrics::GtError& error, const std::string& relations_label) {
  nlohmann::json gt = nlohmann::json::object();
  for (const auto& [key, value] : metrics::GtErrorFields(error)) gt[key] = report::FiniteOrNull(value);
  gt["relations_used"] = error.relations_used;
  gt["relations_missing"] = error.relations_missing;
  gt["relations_file"] = relations_label;
  return gt;
}

nlohmann::json RunJson(const slam::RunSummary& summary, const io::LaserLog& log, const std::string& log_label,
                       const slam::MapperParams& params, const metrics::MapQuality& quality, double map_wall_s) {
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
      {"map_wall_s", map_wall_s},
      {"log_duration_s", summary.log_duration_s},
      {"realtime_factor", summary.wall_s > 0 ? report::FiniteOrNull(summary.log_duration_s / summary.wall_s) : nullptr},
      {"laser_max_range_m", summary.laser_max_range},
      {"range_threshold_m", summary.range_threshold},
      {"no_return_value_m", report::FiniteOrNull(log.no_return_value)},
      {"no_return_rule", log.no_return_rule},
      {"input", io::DescribeLogInput(log)},
      {"params", ParamsJson(params)},
      {"map", MapJson(quality)},
  };
}

double PeakMemoryMb() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss is in KiB on Linux
}

}  // namespace slamtune::tune
