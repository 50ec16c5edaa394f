#include "slamtune/nsga3/nsga3_evaluation.h"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <limits>
#include <map>

#include "slamtune/common/error.h"

namespace slamtune::nsga3 {
namespace {

// slot_of value of an offspring whose fitness was copied from the population.
constexpr std::size_t kFromPopulation = std::numeric_limits<std::size_t>::max();

void RequireFinite(const std::vector<double>& x, const std::vector<double>& f) {
  for (double value : f) {
    if (!std::isfinite(value)) {
      throw InputError(fmt::format(
          "the problem returned objectives [{}] for decision vector [{}]; NSGA-III needs finite objective values",
          fmt::join(f, ", "), fmt::join(x, ", ")));
    }
  }
}

}  // namespace

OffspringEvaluation EvaluateOffspring(const pagmo::problem& problem, const std::optional<pagmo::bfe>& bfe,
                                      const std::vector<std::vector<double>>& population_x,
                                      const std::vector<std::vector<double>>& population_f,
                                      const std::vector<std::vector<double>>& offspring) {
  SLAMTUNE_CHECK(population_x.size() == population_f.size());
  OffspringEvaluation result;
  result.fitness.resize(offspring.size());
  // Known genotypes: the population's (copy the fitness) and the batch's (share a slot).
  std::map<std::vector<double>, std::size_t> population_index;
  for (std::size_t i = 0; i < population_x.size(); ++i) population_index.emplace(population_x[i], i);
  std::map<std::vector<double>, std::size_t> batch_slot;
  std::vector<std::size_t> slot_of(offspring.size());
  std::vector<const std::vector<double>*> unique;  // genotypes to evaluate, in first-seen order
  for (std::size_t k = 0; k < offspring.size(); ++k) {
    if (auto it = population_index.find(offspring[k]); it != population_index.end()) {
      result.fitness[k] = population_f[it->second];
      ++result.copied_from_population;
      slot_of[k] = kFromPopulation;
      continue;
    }
    auto [it, inserted] = batch_slot.emplace(offspring[k], unique.size());
    if (inserted) {
      unique.push_back(&offspring[k]);
    } else {
      ++result.copied_within_batch;
    }
    slot_of[k] = it->second;
  }
  result.evaluated = unique.size();
  if (unique.empty()) return result;

  std::vector<std::vector<double>> values;
  values.reserve(unique.size());
  if (bfe) {
    // One batch call: decision vectors concatenated, fitness vectors returned concatenated.
    const std::size_t nx = problem.get_nx();
    const std::size_t nf = problem.get_nf();
    std::vector<double> flat;
    flat.reserve(unique.size() * nx);
    for (const auto* x : unique) flat.insert(flat.end(), x->begin(), x->end());
    const std::vector<double> flat_f = (*bfe)(problem, flat);
    SLAMTUNE_CHECK(flat_f.size() == unique.size() * nf);
    for (std::size_t u = 0; u < unique.size(); ++u) {
      values.emplace_back(flat_f.begin() + static_cast<std::ptrdiff_t>(u * nf),
                          flat_f.begin() + static_cast<std::ptrdiff_t>((u + 1) * nf));
    }
  } else {
    for (const auto* x : unique) values.push_back(problem.fitness(*x));
  }
  for (std::size_t u = 0; u < unique.size(); ++u) RequireFinite(*unique[u], values[u]);
  for (std::size_t k = 0; k < offspring.size(); ++k) {
    if (slot_of[k] != kFromPopulation) result.fitness[k] = values[slot_of[k]];
  }
  return result;
}

}  // namespace slamtune::nsga3
