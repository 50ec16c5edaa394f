// Sparse Cholesky solve of slam_karto's back-end (docs/engine.md §7.3 step 3): CSparse's
// cs_cholsol, as sba calls it: the upper triangle in compressed columns, natural ordering for
// systems of at most 100 rows and AMD ordering above, and on failure (not positive definite)
// the right-hand side left as it was.
//
// Speed: cs_cholsol redoes the ordering and symbolic analysis at every call, although they
// depend only on the sparsity pattern, which is the same for every iteration of one solve.
// This class keeps the analysis and repeats only the numeric factorisation and the two
// triangular solves, the same calls cs_cholsol makes, so the result is bit-identical (tested
// against cs_cholsol).
#pragma once

#include <memory>
#include <vector>

namespace slamtune::slam {

struct SparseCholeskyOptions {
  int natural_order_max_size = 100;  // sba: AMD ordering when the system has more rows
};

class SparseCholesky {
 public:
  // Analyses the pattern of an n x n upper triangle given in compressed columns
  // (column_starts has n + 1 entries). The arrays are copied.
  SparseCholesky(int n, const std::vector<int>& column_starts, const std::vector<int>& row_indices,
                 const SparseCholeskyOptions& options = {});
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // Factorises the matrix with these values (same pattern) and overwrites b (n entries) with
  // the solution. Returns false, leaving b unchanged, when the factorisation fails.
  bool Solve(const std::vector<double>& values, double* b);

  // Whether the analysis used AMD ordering.
  bool amd_ordering() const { return amd_; }

 private:
  struct Analysis;
  int n_ = 0;
  bool amd_ = false;
  std::vector<int> column_starts_, row_indices_;
  std::unique_ptr<Analysis> analysis_;
};

// One call of CSparse's cs_cholsol on the same data (for tests): order 1 (AMD) when n exceeds
// the option's size, else 0.
bool CsparseCholsol(int n, const std::vector<int>& column_starts, const std::vector<int>& row_indices,
                    const std::vector<double>& values, double* b, const SparseCholeskyOptions& options = {});

}  // namespace slamtune::slam
