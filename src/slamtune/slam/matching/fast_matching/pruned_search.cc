#include "slamtune/slam/matching/fast_matching/pruned_search.h"

#include <algorithm>
#include <bit>
#include <cstring>

#include "slamtune/common/error.h"
#include "slamtune/slam/matching/correlation_grid.h"
#include "slamtune/slam/matching/fast_matching/correlation_kernels.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace slamtune::slam {
namespace {

constexpr int kBlockRows = 4;
constexpr int kBlockColumns = 16;

// dst[p] = max(src[p], src[p + shift]) for p in [0, n); src extends at least shift + 16
// bytes past n, dst at least n bytes.
void MaxWithShifted(const std::uint8_t* src, std::int64_t n, std::int64_t shift, std::uint8_t* dst) {
  std::int64_t p = 0;
#if defined(__SSE2__)
  for (; p + 16 <= n; p += 16) {
    const __m128i a = _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + p));
    const __m128i b = _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + p + shift));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(dst + p), _mm_max_epu8(a, b));
  }
#endif
  for (; p < n; ++p) dst[p] = std::max(src[p], src[p + shift]);
}

// pooled[p] = max of grid[p + 2i + 2j*stride] over i < kBlockColumns, j < kBlockRows (zero
// past the grid), by doubling: shifts 2, 4, ... along rows, then 2, 4, ... rows; two buffers
// in turn. The result is in scratch->pooled.
void PoolGrid(const std::uint8_t* grid, std::int64_t data_size, std::int32_t stride, PrunedSearchScratch* scratch) {
  static_assert(std::has_single_bit(unsigned{kBlockColumns}) && std::has_single_bit(unsigned{kBlockRows}));
  // Zero tails: reads run up to 2 kBlockRows rows + 2 kBlockColumns + 16 bytes past the grid.
  const std::int64_t row = stride;
  const std::size_t size = static_cast<std::size_t>(data_size + 2 * kBlockRows * row + 2 * kBlockColumns + 64);
  std::vector<std::uint8_t>* src = &scratch->pooled_swap;
  std::vector<std::uint8_t>* dst = &scratch->pooled;
  src->assign(size, 0);
  dst->assign(size, 0);
  std::memcpy(src->data(), grid, static_cast<std::size_t>(data_size));
  std::vector<std::int64_t> shifts;
  for (std::int64_t w = 2; w < 2 * kBlockColumns; w *= 2) shifts.push_back(w);
  for (std::int64_t h = 2; h < 2 * kBlockRows; h *= 2) shifts.push_back(h * row);
  for (const std::int64_t shift : shifts) {
    MaxWithShifted(src->data(), data_size, shift, dst->data());
    std::swap(src, dst);
  }
  if (src != &scratch->pooled) scratch->pooled.swap(scratch->pooled_swap);
}

template <typename Acc>
PrunedSearchStats Run(const std::uint8_t* grid, std::int64_t data_size, std::int32_t stride,
                      const ScanLookupTable& table, const CandidateCells& cells,
                      const std::function<bool(std::int32_t, std::int32_t)>& prunable, PrunedSearchScratch* scratch,
                      std::vector<std::int32_t>* sums, std::vector<std::int32_t>* max_sum_at) {
  const int nx = cells.nx, ny = cells.ny, num_angles = table.num_angles();
  const int block_columns = (nx + kBlockColumns - 1) / kBlockColumns;
  const int block_rows = (ny + kBlockRows - 1) / kBlockRows;
  PrunedSearchStats stats;
  stats.blocks = block_columns * block_rows;

  PoolGrid(grid, data_size, stride, scratch);
  const std::uint8_t* pooled = scratch->pooled.data();
  // Bound of a block: max over headings of the pooled sum at its corner candidate (an
  // existing candidate, so safe offsets stay inside the grid), far points counted as 100.
  scratch->order.clear();
  for (int by = 0; by < block_rows; ++by) {
    for (int bx = 0; bx < block_columns; ++bx) {
      const std::int32_t corner =
          cells.index[static_cast<std::size_t>(by * kBlockRows) * nx + static_cast<std::size_t>(bx * kBlockColumns)];
      std::int64_t bound = 0;
      for (int k = 0; k < num_angles; ++k) {
        std::int64_t s = 100 * static_cast<std::int64_t>(table.checked_offsets(k).size());
        for (const std::int32_t o : table.safe_offsets(k)) s += pooled[corner + o];
        bound = std::max(bound, s);
      }
      // Highest bound first; equal bounds in block order (deterministic).
      const std::int64_t block = by * block_columns + bx;
      scratch->order.push_back(((0x7FFFFFFF - bound) << 32) | block);
    }
  }
  std::sort(scratch->order.begin(), scratch->order.end());

  sums->resize(cells.index.size() * static_cast<std::size_t>(num_angles));
  max_sum_at->assign(cells.index.size(), -1);
  internal::RowScratch<Acc> rows;
  std::int32_t best = -1;
  for (const std::int64_t key : scratch->order) {
    const auto bound = static_cast<std::int32_t>(0x7FFFFFFF - (key >> 32));
    if (best >= 0 && prunable(bound, best)) break;  // every remaining block has a bound <= this one
    const int block = static_cast<int>(key & 0xFFFFFFFF);
    const int by = block / block_columns, bx = block % block_columns;
    const int x_begin = bx * kBlockColumns, x_end = std::min(nx, x_begin + kBlockColumns);
    for (int y = by * kBlockRows; y < std::min(ny, (by + 1) * kBlockRows); ++y) {
      const std::size_t row = static_cast<std::size_t>(y) * nx;
      std::int32_t* out = sums->data() + row * num_angles;
      internal::SumStepTwoColumnsFastest<Acc, kBlockColumns>(grid, data_size, table, cells.index[row], x_begin, x_end,
                                                             &rows, out);
      for (int x = x_begin; x < x_end; ++x) {
        const std::int32_t* s = out + static_cast<std::size_t>(x) * num_angles;
        const std::int32_t m = *std::max_element(s, s + num_angles);
        (*max_sum_at)[row + x] = m;
        best = std::max(best, m);
      }
    }
    ++stats.blocks_evaluated;
  }
  return stats;
}

}  // namespace

bool IsStepTwoLattice(const CandidateCells& cells, std::int32_t stride) {
  if (cells.index.empty()) return false;
  const std::int64_t origin = cells.index[0];
  for (int y = 0; y < cells.ny; ++y) {
    for (int x = 0; x < cells.nx; ++x) {
      if (cells.index[static_cast<std::size_t>(y) * cells.nx + x] !=
          origin + 2 * x + 2 * static_cast<std::int64_t>(y) * stride) {
        return false;
      }
    }
  }
  return true;
}

PrunedSearchStats SumCandidatesPruned(const std::uint8_t* grid, std::int64_t data_size, std::int32_t stride,
                                      const ScanLookupTable& table, const CandidateCells& cells,
                                      const std::function<bool(std::int32_t bound, std::int32_t best)>& prunable,
                                      PrunedSearchScratch* scratch, std::vector<std::int32_t>* sums,
                                      std::vector<std::int32_t>* max_sum_at) {
  SLAMTUNE_CHECK(scratch != nullptr && sums != nullptr && max_sum_at != nullptr);
  SLAMTUNE_CHECK(IsStepTwoLattice(cells, stride));
  if (static_cast<std::int64_t>(table.num_beams()) * 100 <= 0xFFFF) {
    return Run<std::uint16_t>(grid, data_size, stride, table, cells, prunable, scratch, sums, max_sum_at);
  }
  return Run<std::uint32_t>(grid, data_size, stride, table, cells, prunable, scratch, sums, max_sum_at);
}

}  // namespace slamtune::slam
