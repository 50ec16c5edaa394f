// Offspring creation for NSGA-III (Deb & Jain 2014, §IV-F and §V-A): random mating,
// simulated binary crossover (SBX) and polynomial mutation, then integer repair.
//
// NSGA-III needs no selection pressure at mating: survival (niching.h) provides it, so
// parents are paired uniformly at random. The operators are pagmo's
// (pagmo/utils/genetic_operators.hpp): SBX on the continuous genes with each gene crossed
// with probability 1/2 when the pair crosses (probability `crossover_probability`), and a
// two-point crossover on the integer genes; polynomial mutation on the continuous genes and a
// uniform integer redraw on the integer genes, each gene with probability
// `mutation_probability`. Note pagmo's SBX derives the spread factor from the lower bound
// only and clamps the children into the bounds. pagmo puts the nix integer genes LAST.
//
// RepairIntegers then rounds every integer gene half away from zero and clamps it into its
// bounds, so an integer gene is always an integer within bounds whatever produced it.
#pragma once

#include <cstddef>
#include <optional>
#include <random>
#include <utility>
#include <vector>

namespace slamtune::nsga3 {

using Bounds = std::pair<std::vector<double>, std::vector<double>>;  // (lower, upper), as pagmo

struct VariationOptions {
  // Probability that a mated pair undergoes crossover; in [0, 1]. Paper: 1.
  double crossover_probability = 1.0;
  // SBX distribution index eta_c; in [1, 100], larger keeps children nearer the parents. Paper: 30.
  double crossover_eta = 30.0;
  // Per-gene mutation probability; in [0, 1]. Unset means 1 / n for n decision variables (paper).
  std::optional<double> mutation_probability;
  // Polynomial mutation distribution index eta_m; in [1, 100]. Paper: 20.
  double mutation_eta = 20.0;

  // Throws InputError naming the field, its value and the rule.
  void Validate() const;
  // The mutation probability used for `dimension` decision variables.
  double MutationProbability(std::size_t dimension) const;
};

// Rounds the last `nix` genes of `x` half away from zero and clamps them into `bounds`.
void RepairIntegers(std::vector<double>& x, const Bounds& bounds, std::size_t nix);

// `count` children of `parents` (non-empty, each of the bounds' dimension, integer genes
// integral): pairs of parents drawn uniformly at random (distinct when there are two or
// more), SBX, polynomial mutation, RepairIntegers. Pairs give two children; an odd count
// drops the last one. Deterministic for a given `rng` state. `options` must be valid.
std::vector<std::vector<double>> MakeOffspring(const std::vector<std::vector<double>>& parents, std::size_t count,
                                               const Bounds& bounds, std::size_t nix, const VariationOptions& options,
                                               std::mt19937& rng);

}  // namespace slamtune::nsga3
