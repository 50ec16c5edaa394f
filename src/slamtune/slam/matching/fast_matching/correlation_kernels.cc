#include "slamtune/slam/matching/fast_matching/correlation_kernels.h"

#include <cstdlib>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define SLAMTUNE_AVX2_KERNELS 1
#endif

namespace slamtune::slam::internal {

#if defined(SLAMTUNE_AVX2_KERNELS)
namespace {

// SumBlock with 32-byte vectors: 32 bytes from p hold candidates l = 0..15 in the low bytes
// of their 16-bit lanes. Compiled for AVX2 by attribute only, so the rest of the program
// stays baseline x86-64 and this code runs only after the CPU check.
struct Avx2Blocks {
  template <typename Acc, int kBlock>
  __attribute__((target("avx2"))) static void Sum(const std::uint8_t* base, std::span<const std::int32_t> offsets,
                                                  Acc* out) {
    static_assert(std::is_same_v<Acc, std::uint16_t> && kBlock % 16 == 0);
    constexpr int kVectors = kBlock / 16;
    __m256i acc[kVectors];
    for (int v = 0; v < kVectors; ++v) acc[v] = _mm256_setzero_si256();
    const __m256i low_bytes = _mm256_set1_epi16(0x00FF);
    for (const std::int32_t o : offsets) {
      const std::uint8_t* p = base + o;
      for (int v = 0; v < kVectors; ++v) {
        const __m256i bytes = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p + 32 * v));
        acc[v] = _mm256_add_epi16(acc[v], _mm256_and_si256(bytes, low_bytes));
      }
    }
    for (int v = 0; v < kVectors; ++v) {
      __m256i* dst = reinterpret_cast<__m256i*>(out + 16 * v);
      _mm256_storeu_si256(dst, _mm256_add_epi16(_mm256_loadu_si256(dst), acc[v]));
    }
  }
};

}  // namespace

// flatten inlines the generic row loop here. The block summer stays one call per block of
// candidates (GCC does not inline it into the generic template), which is small beside its
// loop over every beam.
template <int kBlock>
__attribute__((target("avx2"), flatten)) void SumStepTwoColumnsAvx2(const std::uint8_t* grid, std::int64_t data_size,
                                                                    const ScanLookupTable& table, std::int32_t row0,
                                                                    int x_begin, int x_end,
                                                                    RowScratch<std::uint16_t>* scratch,
                                                                    std::int32_t* out) {
  SumStepTwoColumns<std::uint16_t, kBlock, Avx2Blocks>(grid, data_size, table, row0, x_begin, x_end, scratch, out);
}

bool Avx2Available() {
  static const bool available = __builtin_cpu_supports("avx2");
  return available;
}
#else
template <int kBlock>
void SumStepTwoColumnsAvx2(const std::uint8_t* grid, std::int64_t data_size, const ScanLookupTable& table,
                           std::int32_t row0, int x_begin, int x_end, RowScratch<std::uint16_t>* scratch,
                           std::int32_t* out) {
  SumStepTwoColumns<std::uint16_t, kBlock>(grid, data_size, table, row0, x_begin, x_end, scratch, out);
}

bool Avx2Available() { return false; }
#endif

template void SumStepTwoColumnsAvx2<16>(const std::uint8_t*, std::int64_t, const ScanLookupTable&, std::int32_t, int,
                                        int, RowScratch<std::uint16_t>*, std::int32_t*);
template void SumStepTwoColumnsAvx2<32>(const std::uint8_t*, std::int64_t, const ScanLookupTable&, std::int32_t, int,
                                        int, RowScratch<std::uint16_t>*, std::int32_t*);

bool UseAvx2() {
  static const bool use = Avx2Available() && std::getenv("SLAMTUNE_NO_AVX2") == nullptr;
  return use;
}

}  // namespace slamtune::slam::internal
