#include "slamtune/slam/correlation_search.h"

#include <algorithm>
#include <bit>
#include <cstring>
#include <thread>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

// Below this many byte reads per call the thread start-up costs more than it saves.
constexpr std::int64_t kMinReadsPerThread = 200000;

bool IsStepTwoRow(const std::int32_t* row, int nx) {
  for (int x = 1; x < nx; ++x) {
    if (row[x] != row[0] + 2 * x) return false;
  }
  return true;
}

// floor(a / 2) and ceil(a / 2) for any sign.
std::int64_t FloorHalf(std::int64_t a) { return a >= 0 ? a / 2 : -((-a + 1) / 2); }
std::int64_t CeilHalf(std::int64_t a) { return -FloorHalf(-a); }

// Sums, for kBlock consecutive candidates two cells apart starting at `base`, the bytes at
// base + o + 2l over all offsets o, and adds them to out[0..kBlock). Lanes past the last
// candidate read into the grid's padding and are discarded by the caller.
template <typename Acc, int kBlock>
inline void SumBlock(const std::uint8_t* base, std::span<const std::int32_t> offsets, Acc* out) {
#if defined(__SSE2__)
  if constexpr (std::is_same_v<Acc, std::uint16_t> && std::endian::native == std::endian::little) {
    // 16 bytes from p hold candidates l = 0..7 in the low bytes of their 16-bit lanes: mask
    // the odd bytes and add as 16-bit integers; kBlock/8 accumulators stay in registers.
    // (GCC turns the portable loop below into byte loads and does not vectorise it.)
    constexpr int kVectors = kBlock / 8;
    __m128i acc[kVectors];
    for (int v = 0; v < kVectors; ++v) acc[v] = _mm_setzero_si128();
    const __m128i low_bytes = _mm_set1_epi16(0x00FF);
    for (const std::int32_t o : offsets) {
      const std::uint8_t* p = base + o;
      for (int v = 0; v < kVectors; ++v) {
        const __m128i bytes = _mm_loadu_si128(reinterpret_cast<const __m128i*>(p + 16 * v));
        acc[v] = _mm_add_epi16(acc[v], _mm_and_si128(bytes, low_bytes));
      }
    }
    for (int v = 0; v < kVectors; ++v) {
      __m128i* dst = reinterpret_cast<__m128i*>(out + 8 * v);
      _mm_storeu_si128(dst, _mm_add_epi16(_mm_loadu_si128(dst), acc[v]));
    }
    return;
  }
#endif
  Acc acc[kBlock] = {};
  for (const std::int32_t o : offsets) {
    const std::uint8_t* p = base + o;
    for (int l = 0; l < kBlock; ++l) acc[l] = static_cast<Acc>(acc[l] + p[2 * l]);
  }
  for (int l = 0; l < kBlock; ++l) out[l] = static_cast<Acc>(out[l] + acc[l]);
}

struct PartialOffset {
  std::int32_t offset;
  int first, last;  // candidates x in [first, last] whose summed index is in the grid
};

// Scratch of one worker, reused across rows.
template <typename Acc>
struct RowScratch {
  std::vector<Acc> acc;
  std::vector<std::int32_t> whole_row;  // checked entries in range for the whole row
  std::vector<PartialOffset> partial;   // checked entries in range for part of it
};

// A row whose candidates are two cells apart (every coarse row, §4.5).
template <typename Acc, int kBlock>
void SumStepTwoRow(const std::uint8_t* grid, std::int64_t data_size, const ScanLookupTable& table,
                   std::int32_t row0, int nx, RowScratch<Acc>* scratch, std::int32_t* out) {
  const int num_angles = table.num_angles();
  const int padded = (nx + kBlock - 1) / kBlock * kBlock;
  scratch->acc.resize(static_cast<std::size_t>(padded));
  Acc* acc = scratch->acc.data();
  for (int k = 0; k < num_angles; ++k) {
    // Far points: the summed index must lie in [0, size) (§4.5). Along the row the index grows
    // by 2 per candidate, so the valid candidates form one interval.
    scratch->whole_row.clear();
    scratch->partial.clear();
    for (const std::int32_t o : table.checked_offsets(k)) {
      const std::int64_t start = static_cast<std::int64_t>(row0) + o;
      const std::int64_t first = std::max<std::int64_t>(0, CeilHalf(-start));
      const std::int64_t last = std::min<std::int64_t>(nx - 1, FloorHalf(data_size - 1 - start));
      if (first == 0 && last == nx - 1) {
        scratch->whole_row.push_back(o);
      } else if (first <= last) {
        scratch->partial.push_back({o, static_cast<int>(first), static_cast<int>(last)});
      }
    }
    std::fill(acc, acc + padded, Acc{0});
    for (int x0 = 0; x0 < nx; x0 += kBlock) {
      const std::uint8_t* base = grid + row0 + 2 * x0;
      SumBlock<Acc, kBlock>(base, table.safe_offsets(k), acc + x0);
      SumBlock<Acc, kBlock>(base, scratch->whole_row, acc + x0);
    }
    for (const PartialOffset& p : scratch->partial) {
      const std::uint8_t* base = grid + (static_cast<std::int64_t>(row0) + p.offset);
      for (int x = p.first; x <= p.last; ++x) acc[x] = static_cast<Acc>(acc[x] + base[2 * x]);
    }
    for (int x = 0; x < nx; ++x) out[static_cast<std::size_t>(x) * num_angles + k] = static_cast<std::int32_t>(acc[x]);
  }
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
      SumStepTwoRow<Acc, 16>(grid, data_size, table, row[0], cells.nx, &scratch, out);
    } else {
      SumStepTwoRow<Acc, 32>(grid, data_size, table, row[0], cells.nx, &scratch, out);
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
  const int workers =
      static_cast<int>(std::clamp<std::int64_t>(std::min<std::int64_t>(threads, reads / kMinReadsPerThread), 1,
                                                std::max(cells.ny, 1)));
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
