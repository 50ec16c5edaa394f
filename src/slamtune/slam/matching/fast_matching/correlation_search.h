// The exhaustive correlation of §4.5 (docs/engine.md), reduced to integers: for every
// candidate cell and heading, the sum of the grid bytes under the scan's end points. The
// matcher turns sums into responses (sum / (100 * all beams)), applies penalties and picks
// the best; keeping this inner loop on integers makes it exact in any evaluation order, so
// it can be vectorised and spread over threads and still give Karto's numbers bit for bit
// (the double sum of bytes in Karto is exact, being an integer below 2^53).
//
// Speed (measured in bench/bench_matcher.cc): candidates of a row of the coarse lattice are
// two cells apart, so for one beam the bytes of a block of 16 or 32 candidates are one
// contiguous run of memory; the row kernel keeps 16-bit accumulators of a block in registers
// (fixed trip count, vectorised by the compiler) while it walks the beams. Far points whose
// summed index may leave the grid are clipped to the interval of candidates where it is in
// range, computed once per row and heading. Rows that are not evenly spaced (the fine pass,
// centred on an averaged pose) take the plain per-candidate path.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "slamtune/slam/matching/scan_lookup_table.h"

namespace slamtune::slam {

// The candidate positions of one pass as stored-grid linear indices, y-major (nx per row).
struct CandidateCells {
  int nx = 0;
  int ny = 0;
  std::vector<std::int32_t> index;  // ny * nx
};

// Karto's per-candidate sum (GetResponse numerator, §4.5): adds grid[cell + o] for every
// entry o of `offsets` that is not kInvalidLookup and whose summed index lies in
// [0, data_size). Reference implementation; also used for single cells.
std::int64_t SumCandidate(const std::uint8_t* grid, std::int64_t data_size, std::span<const std::int32_t> offsets,
                          std::int32_t cell_index);

// Fills `sums` (resized to ny*nx*K) with the byte sum of every candidate, index
// (y*nx + x)*K + k, i.e. Karto's loop order y, x, heading. `table` must have been
// partitioned for the range of `cells`, and `grid` must be readable (zero) for 64 bytes past
// data_size (CorrelationGrid::kPadding): the row kernel reads whole blocks of candidates.
// Rows are spread over `threads` threads; the result does not depend on the thread count.
void SumAllCandidates(const std::uint8_t* grid, std::int64_t data_size, const ScanLookupTable& table,
                      const CandidateCells& cells, int threads, std::vector<std::int32_t>* sums);

}  // namespace slamtune::slam
