// Test helpers: the objective set most tests of the selection rules score with, and a record
// that holds just its three objectives.
#pragma once

#include <string>

#include "slamtune/optim/evaluation_record.h"
#include "slamtune/optim/objective_set.h"

namespace slamtune::optim::testing {

// The paper's three objectives (ObjectiveSetKind::kPaper).
inline const ObjectiveSet kPaper{ObjectiveSetKind::kPaper};

// A successful run with the paper's objectives eta, n_c and n_e and `loops` loop closures.
inline EvaluationRecord PaperRecord(const std::string& key, double eta, double nc, double ne, int loops = 1) {
  EvaluationRecord r;
  r.key = key;
  r.occupied_ratio = eta;
  r.corner_pixels = nc;
  r.enclosed_areas = ne;
  r.loop_closures = loops;
  return r;
}

}  // namespace slamtune::optim::testing
