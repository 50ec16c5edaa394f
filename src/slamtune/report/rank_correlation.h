// Spearman's rank correlation, used by the report to ask whether a ground-truth-free map
// objective tracks the true (relations) error of the same SLAM runs.
//
// rho is Pearson's correlation of the ranks (Spearman 1904). Ties share the average of the
// ranks they span ("mid-ranks"), and rho is computed as Pearson on those ranks rather than
// with the 1 - 6 sum d^2 / (n (n^2 - 1)) shortcut, which is exact only without ties
// (Kendall & Gibbons, Rank Correlation Methods, 5th ed., §2.3-2.4).
#pragma once

#include <string>
#include <vector>

namespace slamtune::report {

// 1-based ranks of `values` with ties given their average rank: {10, 20, 20, 30} ->
// {1, 2.5, 2.5, 4}. Values must be finite (a broken invariant otherwise).
std::vector<double> AverageRanks(const std::vector<double>& values);

struct RankCorrelation {
  double rho = 0.0;      // in [-1, 1]; NaN when undefined
  int n = 0;             // pairs used (both values finite)
  int dropped = 0;       // pairs with a NaN or infinite value, left out
  bool defined = false;  // false: fewer than 3 pairs, or one side constant (no ranking)
  std::string note;      // why it is undefined; empty when defined
};

// Spearman's rho of the pairs (x[i], y[i]); x and y must have the same length (a broken
// invariant otherwise).
RankCorrelation SpearmanCorrelation(const std::vector<double>& x, const std::vector<double>& y);

}  // namespace slamtune::report
