// Options of the NSGA-III algorithm (nsga3.h). Defaults follow Deb & Jain 2014, §V-A
// (Table I/II): SBX with p_c = 1 and eta_c = 30, polynomial mutation with p_m = 1/n and
// eta_m = 20, Das-Dennis reference points and N the smallest multiple of 4 not below H.
#pragma once

#include <cstddef>

#include "slamtune/nsga3/normalization.h"
#include "slamtune/nsga3/reference_points.h"
#include "slamtune/nsga3/variation.h"

namespace slamtune::nsga3 {

struct Nsga3Options {
  // Generations run by one evolve() call; 0 returns the population unchanged.
  unsigned generations = 100;
  // Das-Dennis divisions D of the (boundary) reference grid, >= 1; H = C(M + D - 1, D).
  // Ignored when reference_points is given.
  std::size_t divisions = 12;
  // Divisions of the inside layer of §V-B (two-layer points for many objectives); 0 = none.
  // Ignored when reference_points is given.
  std::size_t inner_divisions = 0;
  // User-supplied reference directions (non-negative, non-zero, one per row, M components).
  // Empty = the Das-Dennis grid above.
  ReferencePoints reference_points;
  // Population size N, >= 4, or 0 for the paper's rule: the smallest multiple of 4 that is
  // >= H (Table I: H = 91 -> 92; H = 156 -> 156). evolve() requires the population it is
  // given to have exactly this size (RequiredPopulationSize), so that the run is the
  // configured one rather than whatever the caller happened to build.
  std::size_t population_size = 0;
  // Mating operators.
  VariationOptions variation;
  // Normalisation of the survival candidates.
  NormalizationOptions normalization;
  // Keep the decision and objective vectors of every generation in Nsga3::history()
  // (N * (n + M) doubles per generation); the per-generation counters are always kept.
  bool record_history = false;

  // Throws InputError naming the field, its value and the rule. Checks that need the
  // problem (the dimension of reference_points against M) happen in evolve().
  void Validate() const;

  // The reference points for `objectives` M: reference_points, or the (layered) Das-Dennis
  // grid. Throws InputError when they do not fit M.
  ReferencePoints MakeReferencePoints(std::size_t objectives) const;

  // N for `objectives` M: population_size, or the paper's rule applied to H.
  std::size_t RequiredPopulationSize(std::size_t objectives) const;
};

}  // namespace slamtune::nsga3
