// Whole-engine benchmark: the Karto mapper (slam/log_runner.h) with slam_karto defaults on the
// intel log (skipped when the datasets are absent) and on a simulated world, reporting
// processed scans per second and the real-time factor (log duration / wall time). Each input
// also runs with near-chain skipping off (every near chain matched, slam/matching/fast_matching/response_bound.h), the
// two alternating, so the speed-up of skipping is a ratio from one invocation; the two
// trajectories must be identical.
//
//   bench_engine [--dataset intel] [--world office] [--max-scans N] [--repeat K] [--json]
#include <fmt/format.h>

#include <CLI/CLI.hpp>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/io/carmen/carmen_reader.h"
#include "slamtune/sim/simulation.h"
#include "slamtune/slam/log_runner.h"

namespace {

struct Measurement {
  std::string name;
  int scans = 0;
  int nodes = 0;
  int loops = 0;
  int near_chain_matches = 0;
  int near_chain_skipped = 0;
  double wall_s = 0.0;          // median of `repeat` runs, near-chain skipping on (the default)
  double wall_no_skip_s = 0.0;  // median of `repeat` runs, skipping off
  double log_duration_s = 0.0;
};

double Median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  const std::size_t n = v.size();
  return n % 2 == 1 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

Measurement Measure(const std::string& name, std::shared_ptr<const slamtune::io::LaserLog> log, int repeat) {
  Measurement m;
  m.name = name;
  std::vector<double> on, off;
  std::vector<slamtune::io::TimedPose> reference;
  for (int k = 0; k < repeat; ++k) {
    for (const bool skip : {true, false}) {  // alternating, so both see the same machine
      slamtune::slam::LogRunner runner(log, slamtune::slam::MapperParams{});
      runner.set_skip_unlinkable_near_chains(skip);
      const auto start = std::chrono::steady_clock::now();
      runner.RunToEnd();
      (skip ? on : off).push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
      const slamtune::slam::RunSummary s = runner.Summary();
      const auto trajectory = runner.Trajectory();
      if (reference.empty()) {
        reference = trajectory;
        m.scans = s.scans_read;
        m.nodes = s.nodes;
        m.loops = static_cast<int>(s.loop_closures.size());
        m.near_chain_matches = s.near_chain_matches;
        m.near_chain_skipped = s.near_chain_matches_skipped;
        m.log_duration_s = s.log_duration_s;
      } else if (trajectory.size() != reference.size() ||
                 !std::equal(trajectory.begin(), trajectory.end(), reference.begin(),
                             [](const auto& a, const auto& b) { return a.pose == b.pose; })) {
        throw std::runtime_error(name + ": the trajectory with near-chain skipping " + (skip ? "on" : "off") +
                                 " differs from the first run's");
      }
    }
  }
  m.wall_s = Median(on);
  m.wall_no_skip_s = Median(off);
  return m;
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"Benchmark of the whole Karto engine on a dataset and a simulated world"};
  std::string dataset = "intel";
  std::string world = "office";
  std::size_t max_scans = 0;
  int repeat = 1;
  bool json = false;
  app.add_option("--dataset", dataset, "Dataset name under the shared datasets folder ('' to skip)")
      ->capture_default_str();
  app.add_option("--world", world, "Simulated world ('' to skip)")->capture_default_str();
  app.add_option("--max-scans", max_scans, "Use only the first N scans of the dataset (0 = all)");
  app.add_option("--repeat", repeat, "Runs per input and setting; the median is reported")->capture_default_str();
  app.add_flag("--json", json, "Print JSON");
  CLI11_PARSE(app, argc, argv);

  try {
    std::vector<Measurement> results;
    if (!dataset.empty()) {
      const std::string path = std::string(SLAMTUNE_DATASETS_DIR) + "/" + dataset + ".clf.gz";
      if (std::filesystem::exists(path)) {
        slamtune::io::LogReadOptions options;
        options.max_scans = max_scans;
        auto log = std::make_shared<const slamtune::io::LaserLog>(slamtune::io::ReadCarmenLog(path, options));
        results.push_back(Measure(dataset, log, repeat));
      } else {
        std::fprintf(stderr, "bench_engine: %s not found, dataset skipped\n", path.c_str());
      }
    }
    if (!world.empty()) {
      slamtune::sim::SimulationOptions options;
      options.world = world;
      auto log = std::make_shared<const slamtune::io::LaserLog>(slamtune::sim::Simulate(options).log);
      results.push_back(Measure("sim:" + world, log, repeat));
    }
    nlohmann::json out = nlohmann::json::array();
    for (const Measurement& m : results) {
      const double scans_per_s = m.scans / m.wall_s;
      const double nodes_per_s = m.nodes / m.wall_s;
      const double rtf = m.log_duration_s / m.wall_s;
      if (json) {
        out.push_back({{"input", m.name},
                       {"scans", m.scans},
                       {"nodes", m.nodes},
                       {"loop_closures", m.loops},
                       {"wall_s", m.wall_s},
                       {"log_duration_s", m.log_duration_s},
                       {"scans_per_s", scans_per_s},
                       {"nodes_per_s", nodes_per_s},
                       {"realtime_factor", rtf},
                       {"near_chain_matches", m.near_chain_matches},
                       {"near_chain_matches_skipped", m.near_chain_skipped},
                       {"wall_no_skip_s", m.wall_no_skip_s},
                       {"skip_speedup", m.wall_no_skip_s / m.wall_s}});
      } else {
        std::printf(
            "%-14s %6d scans %5d nodes %3d loops  %8.2f s wall  %8.1f scans/s  %7.1f nodes/s  real-time x%.1f\n",
            m.name.c_str(), m.scans, m.nodes, m.loops, m.wall_s, scans_per_s, nodes_per_s, rtf);
        std::printf(
            "%-14s near chains: %d of %d matches skipped; every near chain matched: %.2f s, so x%.2f "
            "from skipping (medians of %d, same trajectory)\n",
            "", m.near_chain_skipped, m.near_chain_matches, m.wall_no_skip_s, m.wall_no_skip_s / m.wall_s, repeat);
      }
    }
    if (json) std::printf("%s\n", out.dump(2).c_str());
  } catch (const slamtune::InputError& e) {
    std::fprintf(stderr, "bench_engine: error: %s\n", e.what());
    return 2;
  } catch (const std::runtime_error& e) {
    std::fprintf(stderr, "bench_engine: %s\n", e.what());
    return 1;
  }
  return 0;
}
