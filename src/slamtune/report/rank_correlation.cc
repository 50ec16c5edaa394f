// Spearman's rho with mid-ranks (rank_correlation.h).
#include "slamtune/report/rank_correlation.h"

#include <fmt/format.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>

#include "slamtune/common/error.h"

namespace slamtune::report {

std::vector<double> AverageRanks(const std::vector<double>& values) {
  for (double v : values) SLAMTUNE_CHECK_MSG(std::isfinite(v), "AverageRanks needs finite values");
  std::vector<std::size_t> order(values.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return values[a] < values[b]; });
  std::vector<double> ranks(values.size());
  for (std::size_t i = 0; i < order.size();) {
    std::size_t j = i;
    while (j + 1 < order.size() && values[order[j + 1]] == values[order[i]]) ++j;
    // Positions i..j (0-based) hold equal values: each gets the mean of ranks i+1..j+1.
    const double mid = 0.5 * static_cast<double>(i + j) + 1.0;
    for (std::size_t k = i; k <= j; ++k) ranks[order[k]] = mid;
    i = j + 1;
  }
  return ranks;
}

RankCorrelation SpearmanCorrelation(const std::vector<double>& x, const std::vector<double>& y) {
  SLAMTUNE_CHECK_MSG(x.size() == y.size(), "SpearmanCorrelation needs x and y of the same length");
  std::vector<double> fx, fy;
  RankCorrelation out;
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (std::isfinite(x[i]) && std::isfinite(y[i])) {
      fx.push_back(x[i]);
      fy.push_back(y[i]);
    } else {
      ++out.dropped;
    }
  }
  out.n = static_cast<int>(fx.size());
  out.rho = std::numeric_limits<double>::quiet_NaN();
  if (out.n < 3) {
    out.note = fmt::format("only {} usable pairs; at least 3 are needed", out.n);
    return out;
  }
  const std::vector<double> rx = AverageRanks(fx), ry = AverageRanks(fy);
  // Pearson's r of the rank vectors.
  const Eigen::Map<const Eigen::VectorXd> a(rx.data(), out.n), b(ry.data(), out.n);
  const Eigen::VectorXd da = a.array() - a.mean(), db = b.array() - b.mean();
  const double saa = da.squaredNorm(), sbb = db.squaredNorm();
  if (saa == 0.0 || sbb == 0.0) {
    out.note = saa == 0.0 ? "the first variable is constant" : "the second variable is constant";
    return out;
  }
  out.rho = std::clamp(da.dot(db) / std::sqrt(saa * sbb), -1.0, 1.0);
  out.defined = true;
  return out;
}

}  // namespace slamtune::report
