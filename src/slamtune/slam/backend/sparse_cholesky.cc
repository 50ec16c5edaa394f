#include "slamtune/slam/backend/sparse_cholesky.h"

#include <cs.h>

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

// A CSparse view of our arrays (no ownership); CSparse only reads them.
cs_di View(int n, const std::vector<int>& column_starts, const std::vector<int>& row_indices, const double* values) {
  cs_di a{};
  a.nzmax = static_cast<int>(row_indices.size());
  a.m = n;
  a.n = n;
  a.p = const_cast<int*>(column_starts.data());
  a.i = const_cast<int*>(row_indices.data());
  a.x = const_cast<double*>(values);
  a.nz = -1;  // compressed columns
  return a;
}

int Order(int n, const SparseCholeskyOptions& options) { return n > options.natural_order_max_size ? 1 : 0; }

}  // namespace

struct SparseCholesky::Analysis {
  cs_dis* symbolic = nullptr;
  ~Analysis() { cs_di_sfree(symbolic); }
};

SparseCholesky::SparseCholesky(int n, const std::vector<int>& column_starts, const std::vector<int>& row_indices,
                               const SparseCholeskyOptions& options)
    : n_(n),
      amd_(Order(n, options) == 1),
      column_starts_(column_starts),
      row_indices_(row_indices),
      analysis_(std::make_unique<Analysis>()) {
  SLAMTUNE_CHECK(n >= 0 && static_cast<int>(column_starts_.size()) == n + 1);
  const cs_di a = View(n_, column_starts_, row_indices_, nullptr);
  analysis_->symbolic = cs_di_schol(Order(n, options), &a);
}

SparseCholesky::~SparseCholesky() = default;

bool SparseCholesky::Solve(const std::vector<double>& values, double* b) {
  SLAMTUNE_CHECK(values.size() == row_indices_.size());
  const cs_dis* s = analysis_->symbolic;
  if (s == nullptr || n_ == 0) return false;
  const cs_di a = View(n_, column_starts_, row_indices_, values.data());
  cs_din* numeric = cs_di_chol(&a, s);
  if (numeric == nullptr) return false;
  std::vector<double> x(static_cast<std::size_t>(n_));
  cs_di_ipvec(s->pinv, b, x.data(), n_);  // x = P b
  cs_di_lsolve(numeric->L, x.data());     // x = L \ x
  cs_di_ltsolve(numeric->L, x.data());    // x = L' \ x
  cs_di_pvec(s->pinv, x.data(), b, n_);   // b = P' x
  cs_di_nfree(numeric);
  return true;
}

bool CsparseCholsol(int n, const std::vector<int>& column_starts, const std::vector<int>& row_indices,
                    const std::vector<double>& values, double* b, const SparseCholeskyOptions& options) {
  const cs_di a = View(n, column_starts, row_indices, values.data());
  return cs_di_cholsol(Order(n, options), &a, b) != 0;
}

}  // namespace slamtune::slam
