#include "slamtune/sim/relation_sampler.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::sim {
namespace {

// Timestamps are whole microseconds; time rules allow for the rounding of their differences.
constexpr double kTimeTolerance = 1e-7;

void RequirePositive(const char* field, double value) {
  if (!(value > 0.0 && std::isfinite(value))) {
    throw InputError(fmt::format("relations {} = {}: must be positive and finite", field, value));
  }
}

io::Relation MakeRelation(const io::TimedPose& a, const io::TimedPose& b) {
  io::Relation relation;
  relation.t1 = a.time;
  relation.t2 = b.time;
  relation.delta = Between(a.pose, b.pose);
  return relation;
}

}  // namespace

void RelationSamplingOptions::Validate() const {
  if (stride < 1) throw InputError(fmt::format("relations stride = {}: must be >= 1", stride));
  RequirePositive("local_gap_s", local_gap_s);
  RequirePositive("revisit_radius_m", revisit_radius_m);
  RequirePositive("revisit_min_gap_s", revisit_min_gap_s);
  if (!(revisit_max_angle_deg > 0.0 && revisit_max_angle_deg <= 180.0)) {
    throw InputError(fmt::format("relations revisit_max_angle_deg = {}: must be in (0, 180]", revisit_max_angle_deg));
  }
}

RelationSample SampleRelations(const std::vector<io::TimedPose>& truth, const RelationSamplingOptions& options) {
  options.Validate();
  RelationSample sample;
  const double radius2 = options.revisit_radius_m * options.revisit_radius_m;
  const double max_angle = DegToRad(options.revisit_max_angle_deg);
  std::size_t local = 0;  // last scan at least local_gap_s before the current one (moves forward only)
  for (std::size_t j = 0; j < truth.size(); j += options.stride) {
    const io::TimedPose& later = truth[j];
    // Local pair: the latest scan i with t_j - t_i >= gap.
    while (local + 1 < j && later.time - truth[local + 1].time >= options.local_gap_s - kTimeTolerance) ++local;
    if (local < j && later.time - truth[local].time >= options.local_gap_s - kTimeTolerance) {
      sample.relations.push_back(MakeRelation(truth[local], later));
      ++sample.local_pairs;
    }
    // Revisit pair: the nearest earlier scan (earliest on ties) in radius, heading and time gap.
    std::size_t best = j;
    double best_d2 = radius2;
    for (std::size_t i = 0; i < j && later.time - truth[i].time >= options.revisit_min_gap_s - kTimeTolerance; ++i) {
      const double d2 = SquaredDistance(truth[i].pose, later.pose);
      if (d2 <= best_d2 && std::fabs(NormalizeAngle(later.pose.theta - truth[i].pose.theta)) <= max_angle &&
          (best == j || d2 < best_d2)) {
        best = i;
        best_d2 = d2;
      }
    }
    if (best != j) {
      sample.relations.push_back(MakeRelation(truth[best], later));
      ++sample.revisit_pairs;
      sample.longest_revisit_gap_s = std::max(sample.longest_revisit_gap_s, later.time - truth[best].time);
    }
  }
  return sample;
}

}  // namespace slamtune::sim
