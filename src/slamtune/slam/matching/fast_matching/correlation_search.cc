#include "slamtune/slam/matching/fast_matching/correlation_search.h"

#include <algorithm>
#include <thread>

#include "slamtune/common/error.h"
#include "slamtune/slam/matching/fast_matching/correlation_kernels.h"

namespace slamtune::slam {
namespace {

using internal::RowScratch;
using internal::SumStepTwoColumnsFastest;

// Below this many byte reads per call the thread start-up costs more than it saves.
constexpr std::int64_t kMinReadsPerThread = 200000;

bool IsStepTwoRow(const std::int32_t* row, int nx) {
  for (int x = 1; x < nx; ++x) {
    if (row[x] != row[0] + 2 * x) return false;
  }
  return true;
}

// Any other row (the fine pass): candidate by candidate.
void SumIrregularRow(const std::uint8_t* grid, std::int64_t data_size, const ScanLookupTable& table,
                     const std::int32_t* row, int nx, std::int32_t* out) {
  const int num_angles = table.num_angles();
  for (int x = 0; x < nx; ++x) {
    const std::uint8_t* base = grid + row[x];
    for (int k = 0; k < num_angles; ++k) {
      std::int64_t s = 0;
      for (const std::int32_t o : table.safe_offsets(k)) s += base[o];
      for (const std::int32_t o : table.checked_offsets(k)) {
        const std::int64_t idx = static_cast<std::int64_t>(row[x]) + o;
        if (idx >= 0 && idx < data_size) s += grid[idx];
      }
      out[static_cast<std::size_t>(x) * num_angles + k] = static_cast<std::int32_t>(s);
    }
  }
}

template <typename Acc>
void SumRows(const std::uint8_t* grid, std::int64_t data_size, const ScanLookupTable& table,
             const CandidateCells& cells, int y0, int y1, std::int32_t* sums) {
  RowScratch<Acc> scratch;
  const std::size_t row_size = static_cast<std::size_t>(cells.nx) * table.num_angles();
  for (int y = y0; y < y1; ++y) {
    const std::int32_t* row = cells.index.data() + static_cast<std::size_t>(y) * cells.nx;
    std::int32_t* out = sums + static_cast<std::size_t>(y) * row_size;
    if (!IsStepTwoRow(row, cells.nx)) {
      SumIrregularRow(grid, data_size, table, row, cells.nx, out);
    } else if (cells.nx <= 16) {
      SumStepTwoColumnsFastest<Acc, 16>(grid, data_size, table, row[0], 0, cells.nx, &scratch, out);
    } else {
      SumStepTwoColumnsFastest<Acc, 32>(grid, data_size, table, row[0], 0, cells.nx, &scratch, out);
    }
  }
}

}  // namespace

std::int64_t SumCandidate(const std::uint8_t* grid, std::int64_t data_size, std::span<const std::int32_t> offsets,
                          std::int32_t cell_index) {
  std::int64_t sum = 0;
  for (const std::int32_t o : offsets) {
    if (o == kInvalidLookup) continue;
    const std::int64_t idx = static_cast<std::int64_t>(cell_index) + o;
    if (idx < 0 || idx >= data_size) continue;
    sum += grid[idx];
  }
  return sum;
}

void SumAllCandidates(const std::uint8_t* grid, std::int64_t data_size, const ScanLookupTable& table,
                      const CandidateCells& cells, int threads, std::vector<std::int32_t>* sums) {
  SLAMTUNE_CHECK(sums != nullptr && threads >= 1);
  SLAMTUNE_CHECK(static_cast<std::int64_t>(cells.index.size()) == static_cast<std::int64_t>(cells.nx) * cells.ny);
  sums->resize(cells.index.size() * static_cast<std::size_t>(table.num_angles()));
  // 16-bit lanes hold every sum when 100 * beams fits; otherwise 32-bit lanes.
  const bool narrow = static_cast<std::int64_t>(table.num_beams()) * 100 <= 0xFFFF;
  auto run = [&](int y0, int y1) {
    if (narrow) {
      SumRows<std::uint16_t>(grid, data_size, table, cells, y0, y1, sums->data());
    } else {
      SumRows<std::uint32_t>(grid, data_size, table, cells, y0, y1, sums->data());
    }
  };
  const std::int64_t reads = static_cast<std::int64_t>(sums->size()) * table.num_beams();
  const int workers = static_cast<int>(
      std::clamp<std::int64_t>(std::min<std::int64_t>(threads, reads / kMinReadsPerThread), 1, std::max(cells.ny, 1)));
  if (workers <= 1) {
    run(0, cells.ny);
    return;
  }
  // Contiguous blocks of rows; each worker writes only its rows of `sums`.
  std::vector<std::jthread> pool;
  pool.reserve(static_cast<std::size_t>(workers - 1));
  for (int w = 1; w < workers; ++w) {
    pool.emplace_back(run, cells.ny * w / workers, cells.ny * (w + 1) / workers);
  }
  run(0, cells.ny / workers);
}

}  // namespace slamtune::slam
