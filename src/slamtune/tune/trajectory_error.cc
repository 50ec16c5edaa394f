#include "slamtune/tune/trajectory_error.h"

#include "slamtune/common/error.h"
#include "slamtune/io/relations.h"
#include "slamtune/io/trajectory.h"
#include "slamtune/report/json_number.h"

namespace slamtune::tune {

metrics::GtError TrajectoryError(const TrajectoryErrorOptions& options) {
  options.error.Validate();
  const std::vector<io::TimedPose> trajectory = io::ReadTrajectory(options.trajectory);
  const std::vector<io::Relation> relations = io::ReadRelations(options.relations);
  if (relations.empty()) throw InputError(options.relations, 0, "no relations in the file");
  metrics::GtError error = metrics::ComputeGtError(trajectory, relations, options.error);
  if (error.relations_used == 0) {
    throw InputError(options.trajectory, 0,
                     "none of the " + std::to_string(relations.size()) + " relations of " + options.relations +
                         " has both timestamps in the trajectory" +
                         (error.missing_examples.empty() ? "" : " (e.g. " + error.missing_examples[0] + ")"));
  }
  return error;
}

nlohmann::ordered_json ToJson(const metrics::GtError& error) {
  nlohmann::ordered_json out = nlohmann::ordered_json::object();
  for (const auto& [key, value] : metrics::GtErrorFields(error)) {
    out[key] = report::FiniteOrNull<nlohmann::ordered_json>(value);
  }
  out["relations_used"] = error.relations_used;
  out["relations_missing"] = error.relations_missing;
  out["missing_examples"] = error.missing_examples;
  return out;
}

}  // namespace slamtune::tune
