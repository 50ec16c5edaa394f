// How the search progressed, generation by generation: the best value of each objective in
// the population and the hypervolume of its non-dominated front (Zitzler & Thiele, 1999: the
// volume of objective space the front dominates up to a reference point; it grows as the
// front moves towards the ideal point or spreads along it).
//
// The objectives differ in scale by orders of magnitude, so each is normalised to [0, 1] by
// its range over all generations' successful runs, and the reference point is 1.1 in every
// normalised objective (a common choice: the worst point seen still adds volume). The volume is
// exact (pagmo::hypervolume; in 3-D its exact algorithm). Failed runs (their failure scores,
// ObjectiveSet::IsFailureScore) are counted but left out: their scores would stretch the ranges
// and squash every real run together. Values of different runs compare only when their ranges
// do; within one run, a rising curve says the front improved.
#pragma once

#include <vector>

#include "slamtune/optim/objective_set.h"

namespace slamtune::optim {

inline constexpr double kHypervolumeReference = 1.1;  // in every normalised objective

struct GenerationSummary {
  int generation = 0;        // 0 = the initial population
  std::vector<double> best;  // per objective, the lowest value of a successful run; NaN when none
  double hypervolume = 0.0;  // of the normalised non-dominated front; 0 when no run succeeded
  int front_size = 0;        // successful individuals no other successful one dominates
  int failed = 0;            // individuals scored as failed runs
};

struct OptimizationHistory {
  std::vector<double> lower, upper;            // per objective, the range the hypervolume normalises by
  std::vector<GenerationSummary> generations;  // in order
};

// `populations[g]` holds the objective vectors (objectives order) of generation g. Vectors of the
// wrong length count as failed.
OptimizationHistory SummarizeGenerations(const std::vector<std::vector<std::vector<double>>>& populations,
                                         const ObjectiveSet& objectives);

// The hypervolume of `points` (already normalised) up to `reference` in every coordinate;
// points not strictly below the reference in every coordinate add nothing. Any dimension >= 1.
double Hypervolume(const std::vector<std::vector<double>>& points, double reference);

}  // namespace slamtune::optim
