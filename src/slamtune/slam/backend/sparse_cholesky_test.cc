#include "slamtune/slam/backend/sparse_cholesky.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace slamtune::slam {
namespace {

// An n x n symmetric positive definite band-plus-corner matrix, upper triangle in compressed
// columns (rows increasing), values depending on `seed`.
struct Upper {
  int n = 0;
  std::vector<int> starts, rows;
  std::vector<double> values;
};

Upper MakeUpper(int n, double seed) {
  Upper m;
  m.n = n;
  for (int col = 0; col < n; ++col) {
    m.starts.push_back(static_cast<int>(m.rows.size()));
    if (col >= 5) {  // a far coupling, like a loop edge
      m.rows.push_back(col / 7);
      m.values.push_back(0.3 * std::sin(seed * col));
    }
    for (int row = std::max(col - 3, col / 7 + 1); row < col; ++row) {
      m.rows.push_back(row);
      m.values.push_back(0.5 * std::cos(seed * (row + 2 * col)));
    }
    m.rows.push_back(col);
    m.values.push_back(8.0 + std::sin(seed + col));
  }
  m.starts.push_back(static_cast<int>(m.rows.size()));
  return m;
}

std::vector<double> Rhs(int n) {
  std::vector<double> b;
  for (int k = 0; k < n; ++k) b.push_back(std::sin(0.37 * k) + 0.1);
  return b;
}

void ExpectSameAsCholsol(int n) {
  const Upper first = MakeUpper(n, 0.7);
  SparseCholesky cholesky(n, first.starts, first.rows);
  EXPECT_EQ(cholesky.amd_ordering(), n > 100);
  for (double seed : {0.7, 1.3, 2.9}) {  // one analysis, several factorisations
    const Upper m = MakeUpper(n, seed);
    std::vector<double> ours = Rhs(n), theirs = Rhs(n);
    ASSERT_TRUE(cholesky.Solve(m.values, ours.data()));
    ASSERT_TRUE(CsparseCholsol(n, m.starts, m.rows, m.values, theirs.data()));
    EXPECT_EQ(ours, theirs) << "n " << n << " seed " << seed;
  }
}

TEST(SparseCholesky, NaturalOrderingEqualsCholsolBitForBit) { ExpectSameAsCholsol(60); }

TEST(SparseCholesky, AmdOrderingEqualsCholsolBitForBit) { ExpectSameAsCholsol(150); }

TEST(SparseCholesky, SolvesTheSystem) {
  const Upper m = MakeUpper(120, 0.9);
  SparseCholesky cholesky(m.n, m.starts, m.rows);
  std::vector<double> x = Rhs(m.n);
  ASSERT_TRUE(cholesky.Solve(m.values, x.data()));
  // Residual of the symmetric matrix times x against b.
  std::vector<double> ax(static_cast<std::size_t>(m.n), 0.0);
  for (int col = 0; col < m.n; ++col) {
    for (int p = m.starts[col]; p < m.starts[col + 1]; ++p) {
      const int row = m.rows[p];
      ax[row] += m.values[p] * x[col];
      if (row != col) ax[col] += m.values[p] * x[row];
    }
  }
  const std::vector<double> b = Rhs(m.n);
  for (int k = 0; k < m.n; ++k) EXPECT_NEAR(ax[k], b[k], 1e-12) << k;
}

TEST(SparseCholesky, NotPositiveDefiniteLeavesTheRightHandSide) {
  Upper m = MakeUpper(20, 0.5);
  m.values[m.starts[11] - 1] = -1.0;  // diagonal of column 10
  SparseCholesky cholesky(m.n, m.starts, m.rows);
  std::vector<double> b = Rhs(m.n);
  EXPECT_FALSE(cholesky.Solve(m.values, b.data()));
  EXPECT_EQ(b, Rhs(m.n));
  std::vector<double> c = Rhs(m.n);
  EXPECT_FALSE(CsparseCholsol(m.n, m.starts, m.rows, m.values, c.data()));
  EXPECT_EQ(c, Rhs(m.n));
}

}  // namespace
}  // namespace slamtune::slam
