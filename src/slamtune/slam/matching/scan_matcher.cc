// Karto's correlative scan matcher, docs/engine.md §4.2-§4.6. The exhaustive search is
// done on integer byte sums (fast_matching/correlation_search.h) and turned into Karto's responses with
// the same division, penalties and reductions, so results are bit-identical to the
// straightforward double loop (see scan_matcher_test.cc, "MatchesReferenceLoop").
#include "slamtune/slam/matching/scan_matcher.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/slam/matching/correlation_grid.h"
#include "slamtune/slam/matching/fast_matching/correlation_search.h"
#include "slamtune/slam/matching/fast_matching/pruned_search.h"
#include "slamtune/slam/matching/match_covariance.h"
#include "slamtune/slam/matching/scan_lookup_table.h"

namespace slamtune::slam {
namespace {

// Penalty gains of §1.1.
constexpr double kDistancePenaltyGain = 0.2;
constexpr double kAnglePenaltyGain = 0.2;

void RequirePositive(const char* field, double value) {
  if (!(value > 0.0) || !std::isfinite(value)) {
    throw InputError(fmt::format("scan matcher option {} = {}: must be a positive finite number", field, value));
  }
}

}  // namespace

void ScanMatcherOptions::Validate() const {
  RequirePositive("search_dimension", search_dimension);
  RequirePositive("search_resolution", search_resolution);
  RequirePositive("smear_deviation", smear_deviation);
  RequirePositive("range_threshold", range_threshold);
  RequirePositive("coarse_angle_offset", coarse_angle_offset);
  RequirePositive("coarse_angle_resolution", coarse_angle_resolution);
  RequirePositive("fine_angle_step", fine_angle_step);
  RequirePositive("distance_variance_penalty", distance_variance_penalty);
  RequirePositive("angle_variance_penalty", angle_variance_penalty);
  // §4.1 [DECIDE]: the window must hold an odd number of cells with the centre on a cell and
  // the coarse lattice (every second cell) must end on the window edge, i.e. D/rho must be an
  // even integer (within Karto's 1e-6 tolerance). Otherwise Karto's probability-grid lookup
  // can fall outside the grid.
  const double cells = search_dimension / search_resolution;
  const double rounded = KartoRound(cells);
  if (!KartoEqual(rounded, cells) || std::fmod(rounded, 2.0) != 0.0) {
    throw InputError(
        fmt::format("scan matcher option search_dimension / search_resolution = {} / {} = {}: must be an even integer",
                    search_dimension, search_resolution, cells));
  }
  // Karto throws outside [0.5 rho, 10 rho] (the kernel spans 2 sigma, §4.1).
  if (smear_deviation < 0.5 * search_resolution || smear_deviation > 10 * search_resolution) {
    throw InputError(
        fmt::format("scan matcher option smear_deviation = {}: must lie in [0.5, 10] x search_resolution = [{}, {}]",
                    smear_deviation, 0.5 * search_resolution, 10 * search_resolution));
  }
  if (!(minimum_distance_penalty >= 0.0 && minimum_distance_penalty <= 1.0)) {
    throw InputError(
        fmt::format("scan matcher option minimum_distance_penalty = {}: must lie in [0, 1]", minimum_distance_penalty));
  }
  if (!(minimum_angle_penalty >= 0.0 && minimum_angle_penalty <= 1.0)) {
    throw InputError(
        fmt::format("scan matcher option minimum_angle_penalty = {}: must lie in [0, 1]", minimum_angle_penalty));
  }
  if (threads < 1) throw InputError(fmt::format("scan matcher option threads = {}: must be >= 1", threads));
  // Linear indices are 32-bit (§1.2): the stored grid must have fewer than 2^31 cells.
  const auto geometry =
      CorrelationGridGeometry::Compute(search_dimension, search_resolution, smear_deviation, range_threshold);
  if (geometry.data_size() + CorrelationGrid::kPadding >= (std::int64_t{1} << 31)) {
    throw InputError(fmt::format(
        "scan matcher options range_threshold = {}, search_resolution = {}: the correlation grid would have {} "
        "cells, more than 2^31",
        range_threshold, search_resolution, geometry.data_size()));
  }
}

struct ScanMatcher::Impl {
  explicit Impl(const ScanMatcherOptions& o)
      : options(o),
        grid(o.search_dimension, o.search_resolution, o.smear_deviation, o.range_threshold),
        probabilities(grid.geometry().search_side, o.search_resolution) {}

  // The coarse pass samples every second cell of the window and fills the probability grid
  // and the positional covariance; the fine pass samples the cells around the coarse mean and
  // gives the angular variance (§4.2 items 4 and 6).
  enum class Pass { kCoarse, kFine };
  // What one CorrelateScan call searches: the lattice x_j = -offset_xy + j step_xy on both
  // axes around `center`, the headings center.theta +- angle_offset by angle_step.
  struct PassWindow {
    Pose2 center;
    double offset_xy = 0, step_xy = 0;
    double angle_offset = 0, angle_step = 0;
    Penalize penalize = Penalize::kNo;
    Pass pass = Pass::kCoarse;
  };
  // The best response of a pass and, for unpenalised passes, the smallest sum that ties with it.
  struct Best {
    double response = -1.0;  // Karto's start value
    std::int32_t tie_min_sum = 0;
  };

  // CorrelateScan of §4.5; returns min(best, 1) and writes result->mean and the covariance
  // (positional part in the coarse pass, cov(2,2) in the fine pass).
  double CorrelateScan(const LaserScan& scan, const PassWindow& window, MatchResult* result);
  // Steps of CorrelateScan, in order. The lookup table of the pass's headings, the lattice's
  // grid cells and the sum -> response table; returns the lattice side n.
  int SetUpLattice(const LaserScan& scan, const PassWindow& window, ScanLookupTable& table);
  // The byte sum of every candidate (sums), or of those branch and bound cannot skip (then
  // max_sum_at too); returns whether it pruned.
  bool SumCandidates(const PassWindow& window, const ScanLookupTable& table);
  Best PenalizedBest(const PassWindow& window, const ScanLookupTable& table, int n);
  Best UnpenalizedBest(const PassWindow& window, int num_angles, int n, bool pruned);
  // Coarse pass: the probability grid keeps each position's best response over headings.
  void KeepCellMaxima(const Pose2& center, int n);
  Pose2 MeanOfTies(const PassWindow& window, const ScanLookupTable& table, int n, const Best& best);
  // Angular variance from the unpenalised responses at the cell of the mean (§4.6).
  double AngularVarianceAt(const Pose2& average, double best, const PassWindow& window, const ScanLookupTable& table);

  ScanMatcherOptions options;
  CorrelationGrid grid;
  SearchProbabilityGrid probabilities;
  // Buffers reused across calls.
  // Lookup tables of the coarse [0] and fine [1] passes, kept apart so that each can be
  // reused when its inputs repeat (ScanLookupTable::Compute).
  ScanLookupTable tables[2];
  CandidateCells cells;
  std::vector<double> offsets;  // lattice offsets from the centre, both axes
  std::vector<std::int32_t> sums;
  std::vector<double> responses;         // penalised passes only
  std::vector<std::int32_t> max_sum_at;  // unpenalised passes: best sum over headings per position
  std::vector<double> cell_maximum;      // coarse passes: best response over headings per position
  std::vector<double> response_of_sum;   // sum -> sum / (100 * beams), for the current beam count
  PrunedSearchScratch pruned_scratch;
  std::vector<double> heading_cos, heading_sin;  // of the normalised heading alpha_k
  std::vector<double> raw_at_best, angles;       // angular covariance inputs
};

int ScanMatcher::Impl::SetUpLattice(const LaserScan& scan, const PassWindow& window, ScanLookupTable& table) {
  const Pose2& center = window.center;
  // §4.4: lookup tables for the headings of this pass.
  table.Compute(scan, center.theta, window.angle_offset, window.angle_step, grid.roi_origin(), grid.scale(),
                grid.geometry().stride);
  const int num_beams = table.num_beams();
  if (window.pass == Pass::kCoarse) probabilities.Reset({center.x - window.offset_xy, center.y - window.offset_xy});

  // Lattice x_j = -offset + j step, j = 0 .. Round(2 offset / step) (§4.5).
  const int n = static_cast<int>(KartoRound(window.offset_xy * 2.0 / window.step_xy) + 1);
  offsets.resize(static_cast<std::size_t>(n));
  for (int j = 0; j < n; ++j) offsets[static_cast<std::size_t>(j)] = -window.offset_xy + j * window.step_xy;
  cells.nx = cells.ny = n;
  cells.index.resize(static_cast<std::size_t>(n) * n);
  for (int yi = 0; yi < n; ++yi) {
    for (int xi = 0; xi < n; ++xi) {
      const Eigen::Vector2d position(center.x + offsets[static_cast<std::size_t>(xi)],
                                     center.y + offsets[static_cast<std::size_t>(yi)]);
      cells.index[static_cast<std::size_t>(yi) * n + xi] = grid.GridIndex(grid.WorldToGrid(position));
    }
  }
  const auto [min_cell, max_cell] = std::minmax_element(cells.index.begin(), cells.index.end());
  table.Partition(*min_cell, *max_cell, grid.data_size());

  // response = sum / (beams * 100) (§4.5), the divisor counting INVALID beams too. A table
  // indexed by the integer sum gives the same double as dividing each time.
  const double divisor = static_cast<double>(static_cast<std::uint32_t>(num_beams) * 100u);
  const std::size_t max_sum = static_cast<std::size_t>(num_beams) * 100;
  if (response_of_sum.size() != max_sum + 1) {
    response_of_sum.resize(max_sum + 1);
    for (std::size_t s = 0; s <= max_sum; ++s) response_of_sum[s] = static_cast<double>(s) / divisor;
  }
  return n;
}

bool ScanMatcher::Impl::SumCandidates(const PassWindow& window, const ScanLookupTable& table) {
  // Branch and bound pays when the grid is small next to the work (the loop matcher); the
  // pooled copy of a 6 MB sequential grid would cost more than its 16 x 16 search.
  const std::int64_t reads = static_cast<std::int64_t>(cells.index.size()) * table.num_angles() * table.num_beams();
  const bool prune = window.penalize == Penalize::kNo && window.pass == Pass::kCoarse && options.branch_and_bound &&
                     static_cast<std::int64_t>(grid.data_size()) * 8 < reads &&
                     IsStepTwoLattice(cells, grid.geometry().stride);
  if (prune) {
    // Skippable: every sum <= bound gives a response below best - 0.1, which Karto never uses
    // (not the best, not a tie, outside the covariance window; fast_matching/pruned_search.h).
    auto prunable = [this](std::int32_t bound, std::int32_t best_sum) {
      return response_of_sum[static_cast<std::size_t>(bound)] <
             response_of_sum[static_cast<std::size_t>(best_sum)] - 0.1;
    };
    SumCandidatesPruned(grid.data(), grid.data_size(), grid.geometry().stride, table, cells, prunable, &pruned_scratch,
                        &sums, &max_sum_at);
  } else {
    SumAllCandidates(grid.data(), grid.data_size(), table, cells, window.pass == Pass::kFine ? 1 : options.threads,
                     &sums);
  }
  return prune;
}

ScanMatcher::Impl::Best ScanMatcher::Impl::PenalizedBest(const PassWindow& window, const ScanLookupTable& table,
                                                         int n) {
  const int num_angles = table.num_angles();
  const double center_theta = window.center.theta;
  // Responses in Karto's order y, x, heading, with the penalties of §4.5 (offsets from the
  // search centre; not applied to zero responses).
  responses.resize(sums.size());
  for (int yi = 0; yi < n; ++yi) {
    const double y = offsets[static_cast<std::size_t>(yi)];
    for (int xi = 0; xi < n; ++xi) {
      const double x = offsets[static_cast<std::size_t>(xi)];
      const std::size_t base = (static_cast<std::size_t>(yi) * n + xi) * num_angles;
      for (int k = 0; k < num_angles; ++k) {
        double response = response_of_sum[static_cast<std::size_t>(sums[base + k])];
        if (!KartoEqual(response, 0.0)) {
          const double squared_distance = x * x + y * y;
          const double distance_penalty =
              std::max(1.0 - (kDistancePenaltyGain * squared_distance / options.distance_variance_penalty),
                       options.minimum_distance_penalty);
          const double da = table.angle(k) - center_theta;
          const double angle_penalty = std::max(1.0 - (kAnglePenaltyGain * (da * da) / options.angle_variance_penalty),
                                                options.minimum_angle_penalty);
          response *= (distance_penalty * angle_penalty);
        }
        responses[base + k] = response;
      }
    }
  }
  Best best;
  for (const double r : responses) best.response = std::max(best.response, r);
  if (window.pass == Pass::kCoarse) {
    const std::size_t num_cells = static_cast<std::size_t>(n) * n;
    cell_maximum.resize(num_cells);
    for (std::size_t c = 0; c < num_cells; ++c) {
      cell_maximum[c] = *std::max_element(responses.begin() + static_cast<std::ptrdiff_t>(c * num_angles),
                                          responses.begin() + static_cast<std::ptrdiff_t>((c + 1) * num_angles));
    }
  }
  return best;
}

ScanMatcher::Impl::Best ScanMatcher::Impl::UnpenalizedBest(const PassWindow& window, int num_angles, int n,
                                                           bool pruned) {
  // Without penalties the response is an increasing function of the integer sum, so the
  // best response, each position's maximum over headings and the ties (§4.5) are found on
  // the sums: ties are exactly the sums s with |table[s] - best| <= 1e-6, an interval
  // [tie_min_sum, best_sum].
  // (After branch and bound, max_sum_at is already filled, -1 for skipped positions.)
  const std::size_t num_cells = static_cast<std::size_t>(n) * n;
  if (!pruned) {
    max_sum_at.resize(num_cells);
    for (std::size_t c = 0; c < num_cells; ++c) {
      const auto first = sums.begin() + static_cast<std::ptrdiff_t>(c * num_angles);
      max_sum_at[c] = *std::max_element(first, first + num_angles);
    }
  }
  std::int32_t best_sum = 0;
  for (const std::int32_t m : max_sum_at) best_sum = std::max(best_sum, m);
  Best best;
  best.response = std::max(best.response, response_of_sum[static_cast<std::size_t>(best_sum)]);
  best.tie_min_sum = best_sum;
  while (best.tie_min_sum > 0 &&
         KartoEqual(response_of_sum[static_cast<std::size_t>(best.tie_min_sum - 1)], best.response)) {
    --best.tie_min_sum;
  }
  if (window.pass == Pass::kCoarse) {
    cell_maximum.resize(num_cells);
    // A skipped position is below best - 0.1 > 0, so 0 keeps it out of the covariance
    // window exactly as its true value would.
    for (std::size_t c = 0; c < num_cells; ++c) {
      cell_maximum[c] = max_sum_at[c] < 0 ? 0.0 : response_of_sum[static_cast<std::size_t>(max_sum_at[c])];
    }
  }
  return best;
}

void ScanMatcher::Impl::KeepCellMaxima(const Pose2& center, int n) {
  for (int yi = 0; yi < n; ++yi) {
    for (int xi = 0; xi < n; ++xi) {
      double& cell = probabilities.at(probabilities.IndexOf(center.x + offsets[static_cast<std::size_t>(xi)],
                                                            center.y + offsets[static_cast<std::size_t>(yi)]));
      cell = std::max(cell_maximum[static_cast<std::size_t>(yi) * n + xi], cell);
    }
  }
}

Pose2 ScanMatcher::Impl::MeanOfTies(const PassWindow& window, const ScanLookupTable& table, int n, const Best& best) {
  // Mean of every pose whose response equals the best within 1e-6, in loop order:
  // arithmetic mean of positions, circular mean of the normalised headings (§4.5).
  const int num_angles = table.num_angles();
  const bool penalize = window.penalize == Penalize::kYes;
  const Pose2& center = window.center;
  heading_cos.resize(static_cast<std::size_t>(num_angles));
  heading_sin.resize(static_cast<std::size_t>(num_angles));
  for (int k = 0; k < num_angles; ++k) {
    const double heading = NormalizeAngle(table.angle(k));
    heading_cos[static_cast<std::size_t>(k)] = std::cos(heading);
    heading_sin[static_cast<std::size_t>(k)] = std::sin(heading);
  }
  double sum_x = 0.0, sum_y = 0.0, sum_cos = 0.0, sum_sin = 0.0;
  int count = 0;
  for (int yi = 0; yi < n; ++yi) {
    const double position_y = center.y + offsets[static_cast<std::size_t>(yi)];
    for (int xi = 0; xi < n; ++xi) {
      const double position_x = center.x + offsets[static_cast<std::size_t>(xi)];
      const std::size_t cell = static_cast<std::size_t>(yi) * n + xi;
      if (!penalize && max_sum_at[cell] < best.tie_min_sum) continue;
      const std::size_t base = cell * num_angles;
      for (int k = 0; k < num_angles; ++k) {
        const bool tie = penalize ? KartoEqual(responses[base + k], best.response) : sums[base + k] >= best.tie_min_sum;
        if (!tie) continue;
        sum_x += position_x;
        sum_y += position_y;
        sum_cos += heading_cos[static_cast<std::size_t>(k)];
        sum_sin += heading_sin[static_cast<std::size_t>(k)];
        ++count;
      }
    }
  }
  SLAMTUNE_CHECK(count > 0);
  // Karto divides the cosine and sine sums by the count before atan2, as it does the positions.
  return {sum_x / count, sum_y / count, std::atan2(sum_sin / count, sum_cos / count)};
}

double ScanMatcher::Impl::AngularVarianceAt(const Pose2& average, double best, const PassWindow& window,
                                            const ScanLookupTable& table) {
  const int num_angles = table.num_angles();
  const std::int32_t cell = grid.GridIndex(grid.WorldToGrid({average.x, average.y}));
  raw_at_best.resize(static_cast<std::size_t>(num_angles));
  angles.resize(static_cast<std::size_t>(num_angles));
  for (int k = 0; k < num_angles; ++k) {
    const std::int64_t sum = SumCandidate(grid.data(), grid.data_size(), table.offsets(k), cell);
    raw_at_best[static_cast<std::size_t>(k)] = response_of_sum[static_cast<std::size_t>(sum)];
    angles[static_cast<std::size_t>(k)] = table.angle(k);
  }
  return AngularVariance(average.theta, best, window.center.theta, window.angle_step, angles, raw_at_best);
}

double ScanMatcher::Impl::CorrelateScan(const LaserScan& scan, const PassWindow& window, MatchResult* result) {
  ScanLookupTable& table = tables[window.pass == Pass::kFine ? 1 : 0];
  const int n = SetUpLattice(scan, window, table);
  const bool pruned = SumCandidates(window, table);
  const Best best = window.penalize == Penalize::kYes ? PenalizedBest(window, table, n)
                                                      : UnpenalizedBest(window, table.num_angles(), n, pruned);
  if (window.pass == Pass::kCoarse) KeepCellMaxima(window.center, n);
  const Pose2 average = MeanOfTies(window, table, n, best);
  if (window.pass == Pass::kCoarse) {
    result->covariance = PositionalCovariance(average, best.response, window.center, window.offset_xy, window.step_xy,
                                              window.angle_step, probabilities);
  } else {
    result->covariance(2, 2) = AngularVarianceAt(average, best.response, window, table);
  }
  result->mean = average;
  // The covariance above used the unclipped best; the caller sees at most 1 (§4.5).
  return std::min(best.response, 1.0);
}

ScanMatcher::ScanMatcher(const ScanMatcherOptions& options) {
  options.Validate();
  impl_ = std::make_unique<Impl>(options);
}
ScanMatcher::ScanMatcher(const ScanMatcher& other) : impl_(std::make_unique<Impl>(*other.impl_)) {}
ScanMatcher& ScanMatcher::operator=(const ScanMatcher& other) {
  if (this != &other) impl_ = std::make_unique<Impl>(*other.impl_);
  return *this;
}
ScanMatcher::ScanMatcher(ScanMatcher&&) noexcept = default;
ScanMatcher& ScanMatcher::operator=(ScanMatcher&&) noexcept = default;
ScanMatcher::~ScanMatcher() = default;

const ScanMatcherOptions& ScanMatcher::options() const { return impl_->options; }

MatchResult ScanMatcher::Match(const LaserScan& scan, std::span<const LaserScan* const> base_scans, Penalize penalize,
                               Refine refine) {
  SLAMTUNE_CHECK_MSG(impl_ != nullptr, "ScanMatcher used after move");
  // Point readouts are lazy (laser_scan.h): compute them here, before any work is threaded.
  scan.EnsureReadout();
  for (const LaserScan* base : base_scans) base->EnsureReadout();
  Impl& m = *impl_;
  const ScanMatcherOptions& o = m.options;
  MatchResult result;
  const Pose2 center = scan.SensorPose();
  // §4.2 item 1: nothing to match; keep the guess with the weakest covariance.
  if (scan.ranges().empty()) {
    result.mean = center;
    result.covariance(0, 0) = kMaxVariance;
    result.covariance(1, 1) = kMaxVariance;
    result.covariance(2, 2) = 4 * (o.coarse_angle_resolution * o.coarse_angle_resolution);
    result.response = 0.0;
    return result;
  }
  // Karto reads the resolution back from the grid as 1/scale; this is rho for the usual
  // values (0.01, 0.025, 0.05) and keeps Karto's bits otherwise.
  const double resolution = 1.0 / m.grid.scale();
  const CorrelationGridGeometry& g = m.grid.geometry();
  // §4.2 items 2-3: centre the ROI on the sensor position and draw the base scans.
  m.grid.SetRoiOrigin(
      {center.x - (0.5 * (g.roi_side - 1) * resolution), center.y - (0.5 * (g.roi_side - 1) * resolution)});
  m.grid.AddScans(base_scans, {center.x, center.y});

  // §4.2 item 4: coarse pass over every second cell of the window, starting at its edge. With
  // D/rho = 30 (slam_karto's sequential matcher) the centre cell is therefore *not* sampled
  // (only odd offsets -0.15, -0.13, ..., 0.15); with D/rho = 160 (loop) it is. Karto's lattice.
  Impl::PassWindow coarse{.center = center,
                          .offset_xy = 0.5 * (g.search_side - 1) * resolution,
                          .step_xy = 2 * resolution,
                          .angle_offset = o.coarse_angle_offset,
                          .angle_step = o.coarse_angle_resolution,
                          .penalize = penalize,
                          .pass = Impl::Pass::kCoarse};
  double best = m.CorrelateScan(scan, coarse, &result);
  // §4.2 item 5: widen the heading range by 20 degrees at a time, at most 3 times.
  if (o.use_response_expansion && KartoEqual(best, 0.0)) {
    for (int i = 0; i < 3; ++i) {
      coarse.angle_offset += 20 * kRadiansPerDegree;
      best = m.CorrelateScan(scan, coarse, &result);
      if (!KartoEqual(best, 0.0)) break;
    }
  }
  // §4.2 item 6: fine pass, 3x3 cells around the coarse mean, headings within half a coarse
  // step, FineSearchAngleOffset used as the step.
  if (refine == Refine::kYes) {
    const Impl::PassWindow fine{.center = result.mean,
                                .offset_xy = coarse.step_xy * 0.5,
                                .step_xy = resolution,
                                .angle_offset = 0.5 * o.coarse_angle_resolution,
                                .angle_step = o.fine_angle_step,
                                .penalize = penalize,
                                .pass = Impl::Pass::kFine};
    best = m.CorrelateScan(scan, fine, &result);
  }
  result.response = best;
  return result;
}

}  // namespace slamtune::slam
