#include "slamtune/optim/budget_estimate.h"

#include <fmt/format.h>

#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/progress.h"

namespace slamtune::optim {

void BudgetEstimateOptions::Validate() const {
  if (!(warn_after_s > 0.0 && std::isfinite(warn_after_s))) {
    throw InputError(fmt::format("BudgetEstimateOptions.warn_after_s = {}: must be a number > 0", warn_after_s));
  }
}

std::string BudgetEstimateLine(std::size_t population, unsigned generations, std::size_t runs, double seconds,
                               bool early_stop, const BudgetEstimateOptions& options) {
  options.Validate();
  const double per_run = runs > 0 ? seconds / static_cast<double>(runs) : 0.0;
  const double per_generation = per_run * static_cast<double>(population);
  const double rest = per_generation * generations;
  std::string line = fmt::format(
      "generation 0: {} SLAM run{} in {} ({:.1f} s each); the {} generation{} to come take "
      "up to {}",
      runs, runs == 1 ? "" : "s", FormatDuration(seconds), per_run, generations, generations == 1 ? "" : "s",
      FormatDuration(rest));
  line += early_stop ? " (less: repeated parameter sets cost nothing, and the run stops once the answer has settled)"
                     : " (less when parameter sets repeat)";
  if (rest + seconds > options.warn_after_s) {
    line += fmt::format(
        ". That is over {}: a smaller --population or --generations, or more cores (--jobs, mpirun), "
        "shortens it; Ctrl-C keeps every finished run for --resume",
        FormatDuration(options.warn_after_s));
  }
  return line;
}

}  // namespace slamtune::optim
