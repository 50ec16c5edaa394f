// Fitness evaluation of an offspring population for NSGA-III, without duplicate work.
//
// Expensive problems pay seconds to minutes per evaluation (slamtune's: a whole SLAM run), and integer genes
// make identical children common, so a genotype whose fitness is already known is never
// evaluated again: an offspring equal (bit for bit, after integer repair) to a member of the
// current population copies that member's fitness, and an offspring equal to an earlier
// offspring of the same batch shares its evaluation. The remaining unique genotypes go to
// the problem in order, one pagmo::problem::fitness call each, or, when a batch fitness
// evaluator is given, in ONE pagmo::bfe call (which may evaluate them in parallel). Both
// paths give identical values for deterministic problems and count the evaluations in the
// problem's fevals counter.
#pragma once

#include <cstddef>
#include <optional>
#include <pagmo/bfe.hpp>
#include <pagmo/problem.hpp>
#include <vector>

namespace slamtune::nsga3 {

// What the evaluation did.
struct OffspringEvaluation {
  std::vector<std::vector<double>> fitness;  // one per offspring, in order
  std::size_t evaluated = 0;                 // genotypes sent to the problem
  std::size_t copied_from_population = 0;    // offspring equal to a current population member
  std::size_t copied_within_batch = 0;       // offspring equal to an earlier offspring
};

// Evaluates `offspring` on `problem`. `population_x` / `population_f` are the current
// population (same length). Throws InputError if the problem returns a non-finite value, since
// NSGA-III's normalisation needs finite objectives (return a finite penalty instead).
OffspringEvaluation EvaluateOffspring(const pagmo::problem& problem, const std::optional<pagmo::bfe>& bfe,
                                      const std::vector<std::vector<double>>& population_x,
                                      const std::vector<std::vector<double>>& population_f,
                                      const std::vector<std::vector<double>>& offspring);

}  // namespace slamtune::nsga3
