// How sure the recommendation is: the part of the search space that gave an equivalent map.
//
// An evaluation is equivalent to the recommendation when its run succeeded, it closed as many
// loops, and each objective lies within `tolerance` times that objective's range (max - min over
// the successful evaluations) of the recommendation's value. Default 2 %: the objectives rank
// working maps only coarsely (report's caveat), so sets this close are maps the objectives
// cannot tell apart, and a 2 % band still separates a map that broke (its objectives jump by a
// large part of the range) from one that did not. Evaluations are counted once per parameter
// set (the run database may list a set again).
//
// The region is reported per searched parameter as the range of the equivalent sets' values:
// a wide range means the choice is not critical there; a range that is a single value means
// only the recommendation itself (or its neighbours on that parameter's lattice) did as well.
// It is the smallest box around the equivalent sets, not a proof that every set inside it is
// equivalent: sets inside it that were not evaluated are not known.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "slamtune/optim/evaluation_record.h"
#include "slamtune/optim/objective_set.h"
#include "slamtune/optim/search_space.h"

namespace slamtune::optim {

inline constexpr double kEquivalentTolerance = 0.02;  // share of each objective's range

struct ParameterRange {
  std::string name;  // ROS parameter name, SearchSpace order
  double lower = 0.0;
  double upper = 0.0;
  bool integer = false;
};

struct EquivalentRegion {
  double tolerance = kEquivalentTolerance;
  int loop_closures = 0;               // the recommendation's, shared by every member
  std::size_t members = 0;             // distinct parameter sets equivalent to the recommendation (itself included)
  std::size_t evaluated = 0;           // distinct parameter sets whose run succeeded
  std::vector<ParameterRange> ranges;  // one per searched parameter

  // "loop_search_maximum_distance in [3.2, 4.6], loop_match_minimum_chain_size in [8, 14] give an
  // equivalent map (12 of 80 evaluated parameter sets)".
  std::string Describe() const;
};

// Nothing when the recommendation's run failed. The recommendation counts as a member even
// when `evaluations` does not hold it.
std::optional<EquivalentRegion> FindEquivalentRegion(const std::vector<EvaluationRecord>& evaluations,
                                                     const EvaluationRecord& recommended, const SearchSpace& space,
                                                     const ObjectiveSet& objectives,
                                                     double tolerance = kEquivalentTolerance);

}  // namespace slamtune::optim
