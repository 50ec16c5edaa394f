#include "slamtune/report/testing/fake_optimize_result.h"

#include <algorithm>

namespace slamtune::report::testing {

io::MapImage FakeMap(int width, int height) {
  io::MapImage m = io::UniformMap(width, height, io::kMapUnknown);
  m.origin = {-1.0, -2.0, 0.0};
  for (int r = 3; r < height - 3; ++r) {
    for (int c = 3; c < width - 3; ++c) {
      const bool wall = r == 3 || r == height - 4 || c == 3 || c == width - 4;
      m.pixels[static_cast<std::size_t>(r) * width + c] = wall ? io::kMapOccupied : io::kMapFree;
    }
  }
  return m;
}

optim::EvaluationRecord FakeRecord(double r, int g, double quality, bool with_ground_truth) {
  optim::EvaluationRecord e;
  e.params = {{"loop_search_maximum_distance", r},
              {"loop_match_minimum_chain_size", g},
              {"loop_match_minimum_response_coarse", 0.7},
              {"loop_match_maximum_variance_coarse", 0.4}};
  e.key = optim::SearchSpace::Key(e.params);
  e.occupied_ratio = 0.05 + 0.02 * quality;
  e.corner_pixels = 900 + 400 * quality * quality;
  e.enclosed_areas = 12 + static_cast<int>(10 * (1.0 - quality));  // deliberately not monotone the same way
  e.occupied_ratio_known = 0.2 + 0.05 * quality;
  e.corners = 40 + 10 * quality;
  e.contours = 30 + 5 * quality;
  e.hits = 40000;
  e.hits_in_free_cells = 400 + 2000 * quality;
  e.hits_in_unknown_cells = 100;
  e.nodes = 500;
  e.loop_closures = static_cast<int>(12 - 8 * quality);
  for (int i = 0; i < e.loop_closures; ++i) e.loop_scans.push_back(100 + 37 * i);
  e.wall_s = 1.5 + quality;
  if (with_ground_truth) {
    e.has_gt = true;
    e.trans_mean_m = 0.02 + 0.3 * quality;
    e.trans_std_m = 0.01 + 0.1 * quality;
    e.rot_mean_deg = 0.5 + 2 * quality;
    e.rot_std_deg = 0.3 + quality;
    e.relations_used = 250;
  }
  return e;
}

optim::OptimizeResult FakeOptimizeResult(bool with_ground_truth) {
  optim::OptimizeResult res;
  res.source.log_label = "/data/logs/intel.clf.gz";
  res.source.relations_label = with_ground_truth ? "/data/logs/intel.relations" : "";
  res.space = optim::SearchSpace::PaperDefault();
  res.objectives = optim::ObjectiveSet(optim::ObjectiveSetKind::kPaper);
  res.settings = {{"population", 8}, {"generations", 5}, {"seed", 42}, {"jobs", 2}};
  res.population = 8;

  auto candidate = [&](const std::string& label, const std::string& how, double r, int g, double q, bool map) {
    optim::Candidate c;
    c.label = label;
    c.description = how;
    c.record = FakeRecord(r, g, q, with_ground_truth);
    if (map) c.map = FakeMap(60 + static_cast<int>(20 * q), 40);
    return c;
  };
  res.candidates = {candidate("recommended", "shared by most individuals", 3.0, 12, 0.1, true),
                    candidate("knee", "knee of the final front", 3.5, 10, 0.05, true),
                    candidate("worst", "largest normalised objectives", 6.0, 6, 0.9, true),
                    candidate("default", "slam_karto defaults", 4.0, 10, 0.3, false)};
  res.recommended_share = 5;
  res.verdict = "The recommendation <r=3, g=12> beats the defaults & closes more loops.";
  res.lowest_error_label = with_ground_truth ? "knee" : "";

  for (int i = 0; i < 12; ++i) {
    const double q = (i * 7 % 12) / 11.0;
    res.evaluations.push_back(FakeRecord(2.0 + 0.3 * i, 6 + i, q, with_ground_truth));
  }
  res.evaluations.push_back(res.evaluations[3]);  // a repeated key: counted once in the correlation
  res.evaluations.push_back(optim::EvaluationRecord::Failed(
      "k-failed", {{"loop_search_maximum_distance", 5.9}, {"loop_match_minimum_chain_size", 20}},
      "scan matcher threw: bad, \"quoted\" reason"));
  for (int gen : {1, 3, 5}) {
    optim::GenerationSnapshot s;
    s.generation = gen;
    for (int i = 0; i < 8; ++i) {
      const double q = std::min(1.0, (i + 1) / (2.0 * gen));
      const auto rec = FakeRecord(2.0 + 0.5 * i, 6 + i, q, false);
      s.decisions.push_back({2.0 + 0.5 * i, static_cast<double>(6 + i)});
      s.objectives.push_back(res.objectives.Score(rec));
    }
    if (gen == 1) {
      s.decisions.push_back({6.0, 20.0});
      s.objectives.push_back({1.0, 1e9, 1e9});  // a failed individual
    }
    res.snapshots.push_back(s);
  }
  // The history of generations 0..5: the population improves as in the snapshots.
  std::vector<std::vector<std::vector<double>>> populations;
  for (int gen = 0; gen <= 5; ++gen) {
    std::vector<std::vector<double>> f;
    for (int i = 0; i < 8; ++i) {
      const double q = std::min(1.0, (i + 1) / (2.0 * std::max(gen, 1)));
      f.push_back(res.objectives.Score(FakeRecord(2.0 + 0.5 * i, 6 + i, q, false)));
    }
    if (gen == 0) f.push_back({1.0, 1e9, 1e9});  // a failed individual
    populations.push_back(std::move(f));
  }
  res.history = optim::SummarizeGenerations(populations, res.objectives);
  // Sets around the recommendation that gave the same map.
  optim::EquivalentRegion region;
  region.loop_closures = res.candidates[0].record.loop_closures;
  region.members = 4;
  region.evaluated = 12;
  region.ranges = {{"loop_search_maximum_distance", 2.6, 3.5, false}, {"loop_match_minimum_chain_size", 10, 14, true}};
  res.equivalent_region = region;
  res.evaluation_count = 13;
  res.cache_hits = 27;
  res.wall_s = 321.5;
  return res;
}

}  // namespace slamtune::report::testing
