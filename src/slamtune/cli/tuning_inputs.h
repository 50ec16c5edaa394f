// Inputs shared by `slamtune optimize` and `slamtune sweep`: the log (a CARMEN file, or a
// built-in world simulated in memory when none is given), relations, and the base mapper
// parameters from --preset / --params / --set.
#pragma once

#include <CLI/CLI.hpp>

#include <memory>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "slamtune/io/laser_log.h"
#include "slamtune/io/relations.h"
#include "slamtune/slam/mapper_params.h"

namespace slamtune::cli {

struct TuningInputOptions {
  std::string log;             // empty: simulate `world`
  std::string relations;
  std::string world = "office";
  unsigned world_seed = 1;
  std::string preset;
  std::string params_file;
  std::vector<std::string> sets;
  double no_return = 0.0;

  void AddTo(CLI::App& app);
  // Everything that changes results, for the run database and --resume.
  nlohmann::json ToJson() const;
  static TuningInputOptions FromJson(const nlohmann::json& j);
};

struct TuningInputs {
  std::shared_ptr<const io::LaserLog> log;
  std::vector<io::Relation> relations;
  slam::MapperParams base;
  std::string log_label;        // path, or "built-in world NAME (seed N)"
  std::string relations_label;  // path, "simulated", or empty
};

// Loads and validates everything; throws InputError naming the file and problem.
TuningInputs LoadTuningInputs(const TuningInputOptions& options, bool quiet);

}  // namespace slamtune::cli
