#include "slamtune/nsga3/variation.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <pagmo/utils/genetic_operators.hpp>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::nsga3 {
namespace {

void RequireInRange(const char* field, double value, double low, double high) {
  if (!(value >= low && value <= high)) {
    throw InputError(fmt::format("variation.{} = {} is invalid, must be in [{}, {}]", field, value, low, high));
  }
}

}  // namespace

void VariationOptions::Validate() const {
  RequireInRange("crossover_probability", crossover_probability, 0.0, 1.0);
  RequireInRange("crossover_eta", crossover_eta, 1.0, 100.0);
  if (mutation_probability) RequireInRange("mutation_probability", *mutation_probability, 0.0, 1.0);
  RequireInRange("mutation_eta", mutation_eta, 1.0, 100.0);
}

double VariationOptions::MutationProbability(std::size_t dimension) const {
  SLAMTUNE_CHECK(dimension >= 1);
  return mutation_probability.value_or(1.0 / static_cast<double>(dimension));
}

void RepairIntegers(std::vector<double>& x, const Bounds& bounds, std::size_t nix) {
  SLAMTUNE_CHECK(nix <= x.size() && x.size() == bounds.first.size() && x.size() == bounds.second.size());
  for (std::size_t i = x.size() - nix; i < x.size(); ++i) {
    x[i] = std::clamp(KartoRound(x[i]), bounds.first[i], bounds.second[i]);
  }
}

std::vector<std::vector<double>> MakeOffspring(const std::vector<std::vector<double>>& parents, std::size_t count,
                                               const Bounds& bounds, std::size_t nix, const VariationOptions& options,
                                               std::mt19937& rng) {
  SLAMTUNE_CHECK(!parents.empty());
  const std::size_t n = bounds.first.size();
  const double mutation_probability = options.MutationProbability(n);
  std::uniform_int_distribution<std::size_t> pick(0, parents.size() - 1);
  std::vector<std::vector<double>> children;
  children.reserve(count + 1);
  while (children.size() < count) {
    // Random mating (§IV-F): two parents uniformly at random, distinct when possible.
    const std::size_t a = pick(rng);
    std::size_t b = pick(rng);
    while (parents.size() > 1 && b == a) b = pick(rng);
    auto [first, second] = pagmo::sbx_crossover(parents[a], parents[b], bounds, nix, options.crossover_probability,
                                                options.crossover_eta, rng);
    for (std::vector<double>* child : {&first, &second}) {
      pagmo::polynomial_mutation(*child, bounds, nix, mutation_probability, options.mutation_eta, rng);
      RepairIntegers(*child, bounds, nix);
    }
    children.push_back(std::move(first));
    children.push_back(std::move(second));
  }
  children.resize(count);
  return children;
}

}  // namespace slamtune::nsga3
