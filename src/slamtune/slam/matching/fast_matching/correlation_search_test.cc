#include "slamtune/slam/matching/fast_matching/correlation_search.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "slamtune/slam/matching/fast_matching/correlation_kernels.h"

namespace slamtune::slam {
namespace {

// A random byte grid (padded like CorrelationGrid) and a scan with random readings, NaN, inf
// and far "no return" values, so that the table holds safe, checked and INVALID entries.
struct RandomGridAndTable {
  std::vector<std::uint8_t> grid;
  std::int64_t size;
  ScanLookupTable table;

  RandomGridAndTable(int beams, std::uint32_t seed) {
    const std::int32_t stride = 648, height = 645;
    size = static_cast<std::int64_t>(stride) * height;
    std::mt19937 rng(seed);
    std::uniform_int_distribution<int> byte(0, 100);
    grid.assign(static_cast<std::size_t>(size + 64), 0);
    for (std::int64_t i = 0; i < size; ++i) grid[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(byte(rng));
    auto geometry = std::make_shared<LaserGeometry>();
    geometry->min_angle = -kPi / 2;
    geometry->angular_resolution = kPi / beams;
    geometry->num_readings = beams;
    std::uniform_real_distribution<double> range(0.0, 12.0);
    auto ranges = std::make_shared<std::vector<double>>();
    for (int i = 0; i < beams; ++i) {
      const int kind = i % 17;
      ranges->push_back(kind == 3   ? std::nan("")
                        : kind == 5 ? std::numeric_limits<double>::infinity()
                        : kind == 7 ? 81.83
                                    : range(rng));
    }
    const LaserScan scan(geometry, ranges, Pose2{0.4, -0.2, 0.7}, 0.0);
    table.Compute(scan, 0.7, 0.349066, 0.0349066, {-15.6, -16.2}, 20.0, stride);
  }
};

CandidateCells StepTwoLattice(std::int32_t stride) {
  CandidateCells cells;
  cells.nx = cells.ny = 81;
  for (int y = 0; y < 81; ++y) {
    for (int x = 0; x < 81; ++x) cells.index.push_back((242 + 2 * x) + (242 + 2 * y) * stride);
  }
  return cells;
}

CandidateCells IrregularLattice(std::int32_t stride) {
  CandidateCells cells;
  cells.nx = cells.ny = 3;
  const int xs[] = {300, 301, 303};
  const int ys[] = {2, 322, 640};
  for (const int y : ys) {
    for (const int x : xs) cells.index.push_back(x + y * stride);
  }
  return cells;
}

void ExpectMatchesReference(const RandomGridAndTable& f, const CandidateCells& cells, int threads) {
  const auto [lo, hi] = std::minmax_element(cells.index.begin(), cells.index.end());
  ScanLookupTable table = f.table;
  table.Partition(*lo, *hi, f.size);
  EXPECT_GT(table.checked_offsets(0).size(), 0u) << "fixture should exercise the bound check";
  std::vector<std::int32_t> sums;
  SumAllCandidates(f.grid.data(), f.size, table, cells, threads, &sums);
  const int k_count = table.num_angles();
  ASSERT_EQ(sums.size(), cells.index.size() * static_cast<std::size_t>(k_count));
  for (std::size_t c = 0; c < cells.index.size(); ++c) {
    for (int k = 0; k < k_count; ++k) {
      const std::int64_t expected = SumCandidate(f.grid.data(), f.size, table.offsets(k), cells.index[c]);
      ASSERT_EQ(sums[c * k_count + k], expected) << "candidate " << c << " heading " << k;
    }
  }
}

TEST(CorrelationSearch, StepTwoRowsMatchThePerCandidateSum) {
  const RandomGridAndTable f(180, 1);
  ExpectMatchesReference(f, StepTwoLattice(648), 1);
}

TEST(CorrelationSearch, IrregularRowsMatchThePerCandidateSum) {
  const RandomGridAndTable f(180, 2);
  ExpectMatchesReference(f, IrregularLattice(648), 1);
}

TEST(CorrelationSearch, WideScansUse32BitLanes) {
  // 700 beams: 100 * 700 does not fit 16 bits.
  const RandomGridAndTable f(700, 3);
  ExpectMatchesReference(f, StepTwoLattice(648), 1);
  ExpectMatchesReference(f, IrregularLattice(648), 1);
}

// The AVX2 row kernel (used when the CPU has it) against the SSE2/portable one, for both
// block widths, whole and partial column ranges, and rows whose far entries are checked.
TEST(CorrelationSearch, Avx2RowKernelEqualsBaseline) {
  if (!internal::Avx2Available()) GTEST_SKIP() << "CPU without AVX2";
  const RandomGridAndTable f(180, 5);
  ScanLookupTable table = f.table;
  const CandidateCells cells = StepTwoLattice(648);
  const auto [lo, hi] = std::minmax_element(cells.index.begin(), cells.index.end());
  table.Partition(*lo, *hi, f.size);
  const int k_count = table.num_angles();
  internal::RowScratch<std::uint16_t> scratch;
  int compared = 0;
  for (const int y : {0, 40, 80}) {
    const std::int32_t row0 = cells.index[static_cast<std::size_t>(y) * cells.nx];
    for (const auto& [x_begin, x_end] : {std::pair{0, 81}, std::pair{16, 32}, std::pair{3, 50}, std::pair{70, 81}}) {
      std::vector<std::int32_t> base16(81 * k_count, -1), avx16 = base16, base32 = base16, avx32 = base16;
      internal::SumStepTwoColumns<std::uint16_t, 16>(f.grid.data(), f.size, table, row0, x_begin, x_end, &scratch,
                                                     base16.data());
      internal::SumStepTwoColumnsAvx2<16>(f.grid.data(), f.size, table, row0, x_begin, x_end, &scratch, avx16.data());
      internal::SumStepTwoColumns<std::uint16_t, 32>(f.grid.data(), f.size, table, row0, x_begin, x_end, &scratch,
                                                     base32.data());
      internal::SumStepTwoColumnsAvx2<32>(f.grid.data(), f.size, table, row0, x_begin, x_end, &scratch, avx32.data());
      EXPECT_EQ(avx16, base16) << "row " << y << " columns " << x_begin << ".." << x_end;
      EXPECT_EQ(avx32, base32) << "row " << y << " columns " << x_begin << ".." << x_end;
      EXPECT_EQ(base16, base32);
      compared += std::count_if(base16.begin(), base16.end(), [](std::int32_t v) { return v > 0; });
    }
  }
  EXPECT_GT(compared, 1000);
}

TEST(CorrelationSearch, ResultDoesNotDependOnThreads) {
  const RandomGridAndTable f(180, 4);
  ScanLookupTable table = f.table;
  const CandidateCells cells = StepTwoLattice(648);
  const auto [lo, hi] = std::minmax_element(cells.index.begin(), cells.index.end());
  table.Partition(*lo, *hi, f.size);
  std::vector<std::int32_t> one, two, five;
  SumAllCandidates(f.grid.data(), f.size, table, cells, 1, &one);
  SumAllCandidates(f.grid.data(), f.size, table, cells, 2, &two);
  SumAllCandidates(f.grid.data(), f.size, table, cells, 5, &five);
  EXPECT_EQ(one, two);
  EXPECT_EQ(one, five);
}

TEST(CorrelationSearch, SumCandidateSkipsInvalidAndOutOfRangeEntries) {
  const std::vector<std::uint8_t> grid = {10, 20, 30, 40, 50, 0, 0, 0};
  const std::vector<std::int32_t> offsets = {0, 2, -3, 4, kInvalidLookup, 5};
  // cell 1: 1+0 -> 20, 1+2 -> 40, 1-3 < 0 skipped, 1+4 -> 5 >= size 5 skipped, INVALID skipped,
  // 1+5 skipped.
  EXPECT_EQ(SumCandidate(grid.data(), 5, offsets, 1), 60);
}

}  // namespace
}  // namespace slamtune::slam
