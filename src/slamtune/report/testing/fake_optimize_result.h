// A hand-made OptimizeResult for the report's tests: four candidates with tiny maps, a few
// population snapshots and evaluations whose translational error rises with eta (so the
// Spearman correlation of eta is exactly +1), one failed evaluation and one duplicate key.
#pragma once

#include "slamtune/optim/optimize_result.h"

namespace slamtune::report::testing {

// `with_ground_truth`: fill the relations label and every record's errors.
optim::OptimizeResult FakeOptimizeResult(bool with_ground_truth);

// A record for r, g with objectives derived from `quality` (0 best .. 1 worst).
optim::EvaluationRecord FakeRecord(double r, int g, double quality, bool with_ground_truth);

// A small map: unknown border, a free room walled by occupied cells.
io::MapImage FakeMap(int width, int height);

}  // namespace slamtune::report::testing
