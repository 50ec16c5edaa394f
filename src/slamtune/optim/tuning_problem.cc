#include "slamtune/optim/tuning_problem.h"

#include "slamtune/common/error.h"

namespace slamtune::optim {

TuningProblem::TuningProblem(SearchSpace space, ObjectiveSet objectives, std::shared_ptr<BatchEvaluator> evaluator)
    : space_(std::move(space)), objectives_(std::move(objectives)), evaluator_(std::move(evaluator)) {
  space_.Validate("search space");
  SLAMTUNE_CHECK(evaluator_ != nullptr);
}

pagmo::vector_double TuningProblem::fitness(const pagmo::vector_double& x) const {
  SLAMTUNE_CHECK(evaluator_ != nullptr);
  return objectives_.Score(evaluator_->Evaluate({space_.Assign(x)}).front());
}

pagmo::vector_double TuningProblem::batch_fitness(const pagmo::vector_double& xs) const {
  SLAMTUNE_CHECK(evaluator_ != nullptr);
  const std::size_t n = space_.size();
  SLAMTUNE_CHECK(n > 0 && xs.size() % n == 0);
  std::vector<Assignment> batch;
  for (std::size_t i = 0; i < xs.size(); i += n) {
    batch.push_back(
        space_.Assign(pagmo::vector_double(xs.begin() + static_cast<long>(i), xs.begin() + static_cast<long>(i + n))));
  }
  pagmo::vector_double out;
  out.reserve(batch.size() * objectives_.size());
  for (const auto& record : evaluator_->Evaluate(batch)) {
    const auto f = objectives_.Score(record);
    out.insert(out.end(), f.begin(), f.end());
  }
  return out;
}

std::pair<pagmo::vector_double, pagmo::vector_double> TuningProblem::get_bounds() const {
  pagmo::vector_double lo, hi;
  for (const Dimension& d : space_.dimensions) {
    lo.push_back(d.lower);
    hi.push_back(d.upper);
  }
  return {lo, hi};
}

}  // namespace slamtune::optim
