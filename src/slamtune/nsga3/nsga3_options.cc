#include "slamtune/nsga3/nsga3_options.h"

#include <fmt/format.h>

#include <algorithm>

#include "slamtune/common/error.h"

namespace slamtune::nsga3 {

void Nsga3Options::Validate() const {
  if (reference_points.empty() && divisions < 1) {
    throw InputError(fmt::format("nsga3.divisions = {} is invalid, must be >= 1", divisions));
  }
  if (!reference_points.empty()) {
    ValidateReferencePoints(reference_points, reference_points.front().size(), "nsga3.reference_points");
  }
  if (population_size != 0 && population_size < 4) {
    throw InputError(fmt::format("nsga3.population_size = {} is invalid, must be >= 4 (or 0 for the paper's rule)",
                                 population_size));
  }
  variation.Validate();
  normalization.Validate();
}

ReferencePoints Nsga3Options::MakeReferencePoints(std::size_t objectives) const {
  if (reference_points.empty()) return LayeredReferencePoints(objectives, divisions, inner_divisions);
  ValidateReferencePoints(reference_points, objectives, "nsga3.reference_points");
  return reference_points;
}

std::size_t Nsga3Options::RequiredPopulationSize(std::size_t objectives) const {
  if (population_size != 0) return population_size;
  const std::size_t h = MakeReferencePoints(objectives).size();
  return std::max<std::size_t>(4, (h + 3) / 4 * 4);  // §V-A: smallest multiple of 4 >= H
}

}  // namespace slamtune::nsga3
