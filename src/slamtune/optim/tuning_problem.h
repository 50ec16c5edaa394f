// The tuning problem as a pagmo user-defined problem (UDP): decision vector = the search
// space's parameters (reals first, integers last = pagmo's nix), fitness = the map
// objectives of one SLAM run with those parameters (objective_set.h), all minimised. batch_fitness hands a whole
// offspring population to the BatchEvaluator, which deduplicates, serves the run database and runs the rest in
// parallel.
#pragma once

#include <memory>
#include <pagmo/types.hpp>
#include <string>
#include <utility>

#include "slamtune/optim/evaluation/batch_evaluator.h"
#include "slamtune/optim/objective_set.h"
#include "slamtune/optim/search_space.h"

namespace slamtune::optim {

class TuningProblem {
 public:
  TuningProblem() = default;  // pagmo requires it; not usable until constructed properly
  TuningProblem(SearchSpace space, ObjectiveSet objectives, std::shared_ptr<BatchEvaluator> evaluator);

  pagmo::vector_double fitness(const pagmo::vector_double& x) const;
  pagmo::vector_double batch_fitness(const pagmo::vector_double& xs) const;
  std::pair<pagmo::vector_double, pagmo::vector_double> get_bounds() const;
  pagmo::vector_double::size_type get_nobj() const { return objectives_.size(); }
  pagmo::vector_double::size_type get_nix() const { return space_.integer_count(); }
  std::string get_name() const { return "slamtune parameter tuning (" + objectives_.Describe() + ")"; }

  const SearchSpace& space() const { return space_; }

 private:
  SearchSpace space_;
  ObjectiveSet objectives_;
  std::shared_ptr<BatchEvaluator> evaluator_;
};

}  // namespace slamtune::optim
