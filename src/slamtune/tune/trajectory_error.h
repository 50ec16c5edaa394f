// `slamtune gt-error` as library work: the relation-based error (metrics/gt_error.h) of a
// trajectory file (timestamp x y theta per line) against a Freiburg relations file, and the error
// as one JSON object.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "slamtune/metrics/gt_error.h"

namespace slamtune::tune {

struct TrajectoryErrorOptions {
  std::string trajectory;         // timestamp x y theta per line
  std::string relations;          // Freiburg relations: t1 t2 x y z roll pitch yaw per line
  metrics::GtErrorOptions error;  // how poses are matched to relation timestamps
};

// Validates options.error, reads both files and computes the error. InputError for an unreadable
// or malformed file, a relations file without relations, or a trajectory that has both timestamps
// of none of the relations (naming an example).
metrics::GtError TrajectoryError(const TrajectoryErrorOptions& options);

// The error as `gt-error --json` prints it: metrics::GtErrorFields in order (null where not
// finite), then the relations used and missing and the examples of missing ones.
nlohmann::ordered_json ToJson(const metrics::GtError& error);

}  // namespace slamtune::tune
