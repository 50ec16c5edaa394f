// The files `slamtune run` writes beside the map (docs/usage.md, "run"): loop_closures.csv,
// front_end.csv and run.json's parts (counts, timing, laser, input, parameters, map metrics,
// lasers, relation error). Every file is written whole or not at all (common/atomic_file.h).
#pragma once

#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slamtune/io/laser_log.h"
#include "slamtune/metrics/gt_error.h"
#include "slamtune/metrics/map_quality.h"
#include "slamtune/slam/front_end_evidence.h"
#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::tune {

// One row per loop closure: where, which nodes, and its match responses and covariance.
void WriteLoopClosuresCsv(const std::string& path, const slam::RunSummary& summary);

// One row per sequential match (slam/front_end_evidence.h), `suspect` by the run's median response.
void WriteFrontEndCsv(const std::string& path, const std::vector<slam::SequentialMatchStep>& steps,
                      const slam::FrontEndEvidence& evidence);

// Every parameter by its ROS name.
nlohmann::json ParamsJson(const slam::MapperParams& params);

// The map's size and metrics (metrics/map_quality.h).
nlohmann::json MapJson(const metrics::MapQuality& quality);

// The run's Karto lasers (one, or one per beam geometry with --beams per-geometry, docs/engine.md
// §3.5) and the nodes of each.
nlohmann::json LasersJson(const slam::LogLasers& lasers, const slam::RunSummary& summary);

// The relation error (metrics::GtErrorFields, null where not finite), the relations used and
// missing, and the relations' file or origin.
nlohmann::json GtErrorJson(const metrics::GtError& error, const std::string& relations_label);

// run.json's counts, timing, laser, input, parameters and map metrics.
nlohmann::json RunJson(const slam::RunSummary& summary, const io::LaserLog& log, const std::string& log_label,
                       const slam::MapperParams& params, const metrics::MapQuality& quality, double map_wall_s);

// The process's peak resident memory so far, MB.
double PeakMemoryMb();

}  // namespace slamtune::tune
