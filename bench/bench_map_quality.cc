// Speed of the map-quality metrics (metrics/map_quality.h) on synthetic office maps.
//
// The optimiser scores one map per evaluated parameter set, so the metrics must stay far
// below the cost of a SLAM run: the target is a 2000 x 2000 map in well under 100 ms.
//
//   bench_map_quality                       run the benchmarks
//   bench_map_quality --write-maps=DIR      also write the benchmark maps and the docs'
//                                           example maps (map_server YAML + PGM) into DIR
#include <benchmark/benchmark.h>

#include <cstring>
#include <filesystem>
#include <random>
#include <string>
#include <vector>

#include "slamtune/io/map_image.h"
#include "slamtune/metrics/map_quality.h"
#include "slamtune/metrics/synthetic_map.h"

namespace {

using slamtune::metrics::SyntheticRoom;

// A size x size office: a grid of rooms filling `coverage` of the map side, centred, with
// half of them drawn a second time slightly rotated and shifted (a failed loop closure).
// Fixed seed: every run measures the same map.
slamtune::io::MapImage OfficeMap(int size, double coverage) {
  constexpr int kRoomsPerSide = 10;
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> angle(-3.0, 3.0), shift(-2.0, 2.0);
  std::bernoulli_distribution doubled(0.5);
  const double side = size * coverage, pitch = side / kRoomsPerSide, start = (size - side) / 2.0;
  std::vector<SyntheticRoom> rooms;
  for (int i = 0; i < kRoomsPerSide; ++i) {
    for (int j = 0; j < kRoomsPerSide; ++j) {
      const SyntheticRoom room{start + (i + 0.5) * pitch, start + (j + 0.5) * pitch, pitch - 6.0, pitch - 10.0, 0.0};
      rooms.push_back(room);
      if (doubled(rng)) {
        rooms.push_back(
            {room.center_col + shift(rng), room.center_row + shift(rng), room.width, room.height, angle(rng)});
      }
    }
  }
  return slamtune::metrics::DrawSyntheticRooms(size, size, rooms);
}

// The picture in docs/metrics.md: one room, and the same room drawn twice.
void WriteExampleMaps(const std::string& dir) {
  std::filesystem::create_directories(dir);
  const SyntheticRoom room{59.5, 44.5, 90, 60, 0.0};
  const SyntheticRoom second{61.0, 46.0, 90, 60, 4.0};
  slamtune::io::WriteMapServer(slamtune::metrics::DrawSyntheticRooms(120, 90, {room}), dir + "/single_room.yaml");
  slamtune::io::WriteMapServer(slamtune::metrics::DrawSyntheticRooms(120, 90, {room, second}),
                               dir + "/doubled_room.yaml");
  for (int size : {500, 1000, 2000}) {
    slamtune::io::WriteMapServer(OfficeMap(size, 1.0), dir + "/office_" + std::to_string(size) + ".yaml");
  }
}

// Walls spread over the whole map: the crop to the walls' bounding box saves nothing.
void BM_MapQualityFullOffice(benchmark::State& state) {
  const auto map = OfficeMap(static_cast<int>(state.range(0)), 1.0);
  const slamtune::metrics::MapQualityOptions options;
  std::int64_t corner_pixels = 0;
  for (auto _ : state) {
    const auto quality = slamtune::metrics::ComputeMapQuality(map, options);
    corner_pixels = quality.corner_pixels;
    benchmark::DoNotOptimize(corner_pixels);
  }
  state.counters["corner_pixels"] = static_cast<double>(corner_pixels);
  state.counters["Mcells/s"] = benchmark::Counter(static_cast<double>(map.pixels.size()) * state.iterations() / 1e6,
                                                  benchmark::Counter::kIsRate);
}
BENCHMARK(BM_MapQualityFullOffice)->Arg(500)->Arg(1000)->Arg(2000)->Unit(benchmark::kMillisecond);

// A typical SLAM map: walls in the middle 40 % of each side, unknown around them.
void BM_MapQualitySparseOffice(benchmark::State& state) {
  const auto map = OfficeMap(static_cast<int>(state.range(0)), 0.4);
  for (auto _ : state) benchmark::DoNotOptimize(slamtune::metrics::ComputeMapQuality(map).corner_pixels);
}
BENCHMARK(BM_MapQualitySparseOffice)->Arg(2000)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  constexpr const char* kWriteMaps = "--write-maps=";
  std::vector<char*> rest;
  for (int i = 0; i < argc; ++i) {
    if (std::strncmp(argv[i], kWriteMaps, std::strlen(kWriteMaps)) == 0) {
      WriteExampleMaps(argv[i] + std::strlen(kWriteMaps));
    } else {
      rest.push_back(argv[i]);
    }
  }
  int rest_argc = static_cast<int>(rest.size());
  benchmark::Initialize(&rest_argc, rest.data());
  if (benchmark::ReportUnrecognizedArguments(rest_argc, rest.data())) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  return 0;
}
