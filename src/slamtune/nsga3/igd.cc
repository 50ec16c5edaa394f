#include "slamtune/nsga3/igd.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "slamtune/common/error.h"

namespace slamtune::nsga3 {

double InvertedGenerationalDistance(const std::vector<std::vector<double>>& targets,
                                    const std::vector<std::vector<double>>& obtained) {
  SLAMTUNE_CHECK(!targets.empty() && !obtained.empty());
  double total = 0.0;
  for (const auto& z : targets) {
    double nearest = std::numeric_limits<double>::infinity();
    for (const auto& a : obtained) {
      SLAMTUNE_CHECK(a.size() == z.size());
      double d2 = 0.0;
      for (std::size_t i = 0; i < z.size(); ++i) d2 += (z[i] - a[i]) * (z[i] - a[i]);
      nearest = std::min(nearest, d2);
    }
    total += std::sqrt(nearest);  // eq. 6
  }
  return total / static_cast<double>(targets.size());
}

std::vector<std::vector<double>> TargetsOnSimplex(const std::vector<std::vector<double>>& directions, double sum) {
  std::vector<std::vector<double>> targets;
  targets.reserve(directions.size());
  for (std::vector<double> w : directions) {
    const double total = std::accumulate(w.begin(), w.end(), 0.0);
    SLAMTUNE_CHECK(total > 0.0);
    for (double& c : w) c *= sum / total;
    targets.push_back(std::move(w));
  }
  return targets;
}

std::vector<std::vector<double>> TargetsOnUnitSphere(const std::vector<std::vector<double>>& directions) {
  std::vector<std::vector<double>> targets;
  targets.reserve(directions.size());
  for (std::vector<double> w : directions) {
    const double norm = std::sqrt(std::inner_product(w.begin(), w.end(), w.begin(), 0.0));
    SLAMTUNE_CHECK(norm > 0.0);
    for (double& c : w) c /= norm;
    targets.push_back(std::move(w));
  }
  return targets;
}

}  // namespace slamtune::nsga3
