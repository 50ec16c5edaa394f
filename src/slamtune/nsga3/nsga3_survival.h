// Survival step of NSGA-III (Deb & Jain 2014, Algorithm 1, steps 3-17).
//
// Given the objective vectors of R_t = P_t u Q_t (2N members), sort them into
// non-dominated fronts (pagmo::fast_non_dominated_sorting) and take whole fronts
// F_1, F_2, ... into S_t until |S_t| >= N. If that lands exactly on N, S_t survives.
// Otherwise P_{t+1} = F_1 u ... u F_{l-1}, and the K = N - |P_{t+1}| remaining places go
// to members of the last front F_l chosen by reference-point niching: S_t is normalised
// (normalization.h), associated with the reference lines and the niche counts of P_{t+1}
// drive Algorithm 4 (niching.h).
#pragma once

#include <cstddef>
#include <optional>
#include <random>
#include <vector>

#include "slamtune/nsga3/normalization.h"
#include "slamtune/nsga3/reference_points.h"

namespace slamtune::nsga3 {

// What the survival step did and why.
struct SurvivalResult {
  std::vector<std::size_t> survivors;          // indices into the combined population, N of them
  std::size_t fronts_used = 0;                 // l: the fronts that entered S_t
  std::size_t last_front_size = 0;             // |F_l|
  std::size_t niched = 0;                      // K: members of F_l chosen by niching (0 if S_t fit exactly)
  std::size_t excluded_references = 0;         // reference points excluded during niching
  std::optional<Normalization> normalization;  // set when niching ran
};

// Selects `n` survivors (1 <= n <= objectives.size(), objectives.size() >= 2, finite values of
// one common dimension M equal to that of the reference points). `earlier_ideal` is the ideal
// point of the earlier generations (M values, or empty), see ComputeNormalization. `options`
// must be valid.
SurvivalResult SelectSurvivors(const std::vector<std::vector<double>>& objectives, std::size_t n,
                               const ReferencePoints& reference_points, const NormalizationOptions& options,
                               std::mt19937& rng, const std::vector<double>& earlier_ideal = {});

}  // namespace slamtune::nsga3
