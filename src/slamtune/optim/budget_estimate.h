// What an optimisation will cost, said after its first generation (the initial population, all
// new parameter sets): a real log at the seed paper's budget is thousands of SLAM runs, hours on
// a laptop, and a user should learn that in the first minute, not the fifth hour.
#pragma once

#include <cstddef>
#include <string>

namespace slamtune::optim {

struct BudgetEstimateOptions {
  double warn_after_s = 1800.0;  // s: a budget longer than this gets advice on shortening it, > 0

  void Validate() const;
};

// One line: the initial population's `runs` SLAM runs took `seconds`; the `generations` still
// to come, `population` parameter sets each, take up to generations x that (repeated parameter
// sets are served from the run database and the early stop usually ends sooner, so it is an
// upper bound); with advice when it exceeds options.warn_after_s.
std::string BudgetEstimateLine(std::size_t population, unsigned generations, std::size_t runs, double seconds,
                               bool early_stop, const BudgetEstimateOptions& options = {});

}  // namespace slamtune::optim
