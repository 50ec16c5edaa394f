// Test helper: the objective set most tests of the selection rules score with.
#pragma once

#include "slamtune/optim/objective_set.h"

namespace slamtune::optim::testing {

// The paper's three objectives (ObjectiveSetKind::kPaper).
inline const ObjectiveSet kPaper{ObjectiveSetKind::kPaper};

}  // namespace slamtune::optim::testing
