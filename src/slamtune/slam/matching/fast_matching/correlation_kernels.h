// Inner kernels of the correlative search (docs/engine.md §4.5), shared by the
// exhaustive search (correlation_search.cc) and the branch and bound (pruned_search.cc).
// Internal to fast_matching/.
//
// A coarse lattice row has its candidates two cells apart, so for one beam the bytes of a
// block of 8, 16 or 32 candidates are one contiguous run of memory. SumBlock keeps 16-bit
// accumulators of a block in registers (SSE2: one 16-byte load, a mask of the odd bytes and
// a 16-bit add cover 8 candidates) while it walks the beams. Integer sums are exact, so the
// order of additions does not matter, and the AVX2 variant (correlation_kernels.cc, 16
// candidates per 32-byte vector, picked at run time) gives the same sums.
#pragma once

#include <algorithm>
#include <bit>
#include <cstdint>
#include <span>
#include <type_traits>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "slamtune/slam/matching/scan_lookup_table.h"

namespace slamtune::slam::internal {

// floor(a / 2) and ceil(a / 2) for any sign.
inline std::int64_t FloorHalf(std::int64_t a) { return a >= 0 ? a / 2 : -((-a + 1) / 2); }
inline std::int64_t CeilHalf(std::int64_t a) { return -FloorHalf(-a); }

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

// The block summer of SumStepTwoColumns: SumBlock (SSE2 or portable).
struct BaselineBlocks {
  template <typename Acc, int kBlock>
  static void Sum(const std::uint8_t* base, std::span<const std::int32_t> offsets, Acc* out) {
    SumBlock<Acc, kBlock>(base, offsets, out);
  }
};

// Candidates x in [x_begin, x_end) of a row whose candidates are two cells apart (every
// coarse row, §4.5): candidate x has stored index row0 + 2x. Writes out[x*K + k] for every
// heading k. The grid must be readable 2*kBlock bytes past data_size (zero padding).
template <typename Acc, int kBlock, typename Blocks = BaselineBlocks>
void SumStepTwoColumns(const std::uint8_t* grid, std::int64_t data_size, const ScanLookupTable& table,
                       std::int32_t row0, int x_begin, int x_end, RowScratch<Acc>* scratch, std::int32_t* out) {
  const int num_angles = table.num_angles();
  const int width = x_end - x_begin;
  const int padded = (width + kBlock - 1) / kBlock * kBlock;
  scratch->acc.resize(static_cast<std::size_t>(padded));
  Acc* acc = scratch->acc.data();
  for (int k = 0; k < num_angles; ++k) {
    // Far points: the summed index must lie in [0, size) (§4.5). Along the row the index grows
    // by 2 per candidate, so the valid candidates form one interval.
    scratch->whole_row.clear();
    scratch->partial.clear();
    for (const std::int32_t o : table.checked_offsets(k)) {
      const std::int64_t start = static_cast<std::int64_t>(row0) + o;
      const std::int64_t first = std::max<std::int64_t>(x_begin, CeilHalf(-start));
      const std::int64_t last = std::min<std::int64_t>(x_end - 1, FloorHalf(data_size - 1 - start));
      if (first == x_begin && last == x_end - 1) {
        scratch->whole_row.push_back(o);
      } else if (first <= last) {
        scratch->partial.push_back({o, static_cast<int>(first), static_cast<int>(last)});
      }
    }
    std::fill(acc, acc + padded, Acc{0});
    for (int x0 = x_begin; x0 < x_end; x0 += kBlock) {
      const std::uint8_t* base = grid + row0 + 2 * x0;
      Blocks::template Sum<Acc, kBlock>(base, table.safe_offsets(k), acc + (x0 - x_begin));
      Blocks::template Sum<Acc, kBlock>(base, scratch->whole_row, acc + (x0 - x_begin));
    }
    for (const PartialOffset& p : scratch->partial) {
      const std::uint8_t* base = grid + (static_cast<std::int64_t>(row0) + p.offset);
      for (int x = p.first; x <= p.last; ++x) acc[x - x_begin] = static_cast<Acc>(acc[x - x_begin] + base[2 * x]);
    }
    for (int x = x_begin; x < x_end; ++x) {
      out[static_cast<std::size_t>(x) * num_angles + k] = static_cast<std::int32_t>(acc[x - x_begin]);
    }
  }
}

// The same sums with 32-byte AVX2 vectors (16 candidates per vector), for 16-bit
// accumulators and kBlock 16 or 32. Integer sums, so the results equal SumStepTwoColumns'
// bit for bit (tested). Call only when Avx2Available(); defined in correlation_kernels.cc.
template <int kBlock>
void SumStepTwoColumnsAvx2(const std::uint8_t* grid, std::int64_t data_size, const ScanLookupTable& table,
                           std::int32_t row0, int x_begin, int x_end, RowScratch<std::uint16_t>* scratch,
                           std::int32_t* out);

// Whether this CPU runs the AVX2 kernels (checked once), and the switch the search uses:
// AVX2 when available unless SLAMTUNE_NO_AVX2 is set in the environment.
bool Avx2Available();
bool UseAvx2();

// Dispatches one step-two row to the AVX2 or the baseline kernel.
template <typename Acc, int kBlock>
void SumStepTwoColumnsFastest(const std::uint8_t* grid, std::int64_t data_size, const ScanLookupTable& table,
                              std::int32_t row0, int x_begin, int x_end, RowScratch<Acc>* scratch, std::int32_t* out) {
  if constexpr (std::is_same_v<Acc, std::uint16_t> && (kBlock == 16 || kBlock == 32)) {
    if (UseAvx2()) {
      SumStepTwoColumnsAvx2<kBlock>(grid, data_size, table, row0, x_begin, x_end, scratch, out);
      return;
    }
  }
  SumStepTwoColumns<Acc, kBlock>(grid, data_size, table, row0, x_begin, x_end, scratch, out);
}

}  // namespace slamtune::slam::internal
