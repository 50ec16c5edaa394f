// Branch and bound over the coarse lattice of an unpenalised correlative search
// (docs/engine.md §4.5, §4.6), giving exactly the numbers of the exhaustive search.
//
// Why it is exact: without penalties a candidate's response is an increasing function of its
// integer byte sum. Karto uses a candidate's response only (a) for the best response, (b) for
// the ties within 1e-6 of the best (the mean), and (c) in the positional covariance, which
// keeps only positions whose best response over headings is >= best - 0.1. A candidate whose
// response is provably below best - 0.1 therefore changes nothing, and its sum need not be
// computed. The proof is a bound: candidates are grouped in blocks of 4 rows x 8 columns, and
// the grid max-pooled over such a block (cells 2 apart, as the candidates) gives, summed over
// a heading's beams, an upper bound of every sum in the block (far points that may leave the
// grid count 100). Blocks are evaluated exactly in decreasing order of their bound until the
// bound's response drops below best - 0.1 of the best found so far (in the caller's double
// arithmetic); the rest are skipped. This is the multi-resolution idea of Olson's
// correlative matching (ICRA 2009), used here only where it cannot change a result.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "slamtune/slam/matching/fast_matching/correlation_search.h"
#include "slamtune/slam/matching/scan_lookup_table.h"

namespace slamtune::slam {

struct PrunedSearchStats {
  int blocks = 0;            // blocks of the lattice
  int blocks_evaluated = 0;  // blocks whose sums were computed exactly
};

// Whether the lattice is the coarse one the bound needs: index(y, x) = index(0, 0) + 2x +
// 2y*stride for every candidate.
bool IsStepTwoLattice(const CandidateCells& cells, std::int32_t stride);

// Scratch of the branch and bound, reused across calls.
struct PrunedSearchScratch {
  std::vector<std::uint8_t> pooled, pooled_swap;
  std::vector<std::int64_t> order;  // (bound << 32) | block, sorted
};

// Computes sums (index (y*nx + x)*K + k, as SumAllCandidates) for the candidates of every
// block that may matter, and max_sum_at[y*nx + x] = the best sum over headings, or -1 for the
// candidates of skipped blocks (whose sums are left unset). `prunable(bound, best)` says
// whether every candidate with sum <= bound is below the best response - 0.1 when the best
// sum so far is `best`; it must be monotone (true for a bound stays true for lower bounds and
// higher bests). `table` must be partitioned for `cells`; `grid` padded as for
// SumAllCandidates.
PrunedSearchStats SumCandidatesPruned(const std::uint8_t* grid, std::int64_t data_size, std::int32_t stride,
                                      const ScanLookupTable& table, const CandidateCells& cells,
                                      const std::function<bool(std::int32_t bound, std::int32_t best)>& prunable,
                                      PrunedSearchScratch* scratch, std::vector<std::int32_t>* sums,
                                      std::vector<std::int32_t>* max_sum_at);

}  // namespace slamtune::slam
