// `slamtune gt-error TRAJECTORY RELATIONS`: relation-based error of a trajectory against the
// Freiburg ground-truth relations (metrics/gt_error.h), as text or JSON.
#include <cmath>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

#include "slamtune/cli/command_registry.h"
#include "slamtune/common/error.h"
#include "slamtune/io/relations.h"
#include "slamtune/io/trajectory.h"
#include "slamtune/metrics/gt_error.h"

namespace slamtune::cli {
namespace {

struct GtErrorArgs {
  std::string trajectory;
  std::string relations;
  bool json = false;
  metrics::GtErrorOptions options;
};

nlohmann::ordered_json ToJson(const metrics::GtError& e) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [key, value] : metrics::GtErrorFields(e)) {
    out[key] = std::isfinite(value) ? nlohmann::ordered_json(value) : nlohmann::ordered_json(nullptr);  // NaN -> null
  }
  out["relations_used"] = e.relations_used;
  out["relations_missing"] = e.relations_missing;
  out["missing_examples"] = e.missing_examples;
  return out;
}

const SubcommandRegistrar kGtError(Subcommand{
    "gt-error",
    "Relation-based error (Kuemmerle et al. 2009) of a trajectory (timestamp x y theta) against "
    "ground-truth relations (t1 t2 x y z roll pitch yaw)",
    60, [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<GtErrorArgs>();
      app.add_option("TRAJECTORY", args->trajectory, "Trajectory file: timestamp x y theta per line")->required();
      app.add_option("RELATIONS", args->relations, "Freiburg relations file")->required();
      app.add_flag("--json", args->json, "Print the result as one JSON object");
      app.add_option("--time-tolerance", args->options.time_tolerance_s,
                     "Largest timestamp difference (s) for a pose to match a relation timestamp")
          ->capture_default_str();
      app.footer(
          "Examples:\n"
          "  slamtune gt-error runs/intel/trajectory.txt intel.relations\n"
          "  slamtune gt-error trajectory.txt aces.relations --json");
      return [args]() -> int {
        args->options.Validate();
        const auto trajectory = io::ReadTrajectory(args->trajectory);
        const auto relations = io::ReadRelations(args->relations);
        if (relations.empty()) throw InputError(args->relations, 0, "no relations in the file");
        const metrics::GtError error = metrics::ComputeGtError(trajectory, relations, args->options);
        if (error.relations_used == 0) {
          throw InputError(args->trajectory, 0,
                           "none of the " + std::to_string(relations.size()) + " relations of " + args->relations +
                               " has both timestamps in the trajectory" +
                               (error.missing_examples.empty() ? "" : " (e.g. " + error.missing_examples[0] + ")"));
        }
        if (args->json) {
          std::printf("%s\n", ToJson(error).dump(2).c_str());
        } else {
          std::printf("%s", metrics::FormatGtError(error).c_str());
        }
        return 0;
      };
    }});

}  // namespace
}  // namespace slamtune::cli
