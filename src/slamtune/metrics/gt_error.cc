#include "slamtune/metrics/gt_error.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::metrics {
namespace {

struct MeanStd {
  double mean = std::numeric_limits<double>::quiet_NaN();
  double std = std::numeric_limits<double>::quiet_NaN();
};

// Mean and sample standard deviation (two passes; n - 1 divisor, 0 for a single value).
MeanStd Stats(const std::vector<double>& values) {
  MeanStd out;
  if (values.empty()) return out;
  double sum = 0.0;
  for (const double v : values) sum += v;
  out.mean = sum / static_cast<double>(values.size());
  if (values.size() == 1) {
    out.std = 0.0;
    return out;
  }
  double squares = 0.0;
  for (const double v : values) squares += (v - out.mean) * (v - out.mean);
  out.std = std::sqrt(squares / static_cast<double>(values.size() - 1));
  return out;
}

// Trajectory poses sorted by time, for nearest-timestamp lookup within a tolerance.
class PoseLookup {
 public:
  PoseLookup(const std::vector<io::TimedPose>& trajectory, double tolerance)
      : poses_(trajectory), tolerance_(tolerance) {
    std::stable_sort(poses_.begin(), poses_.end(),
                     [](const io::TimedPose& a, const io::TimedPose& b) { return a.time < b.time; });
  }

  // The pose whose time is nearest to t, if it is within the tolerance.
  std::optional<Pose2> Find(double t) const {
    auto it = std::lower_bound(poses_.begin(), poses_.end(), t - tolerance_,
                               [](const io::TimedPose& p, double time) { return p.time < time; });
    std::optional<Pose2> best;
    double best_gap = std::numeric_limits<double>::infinity();
    for (; it != poses_.end() && it->time <= t + tolerance_; ++it) {
      const double gap = std::fabs(it->time - t);
      if (gap < best_gap) {
        best_gap = gap;
        best = it->pose;
      }
    }
    return best;
  }

 private:
  std::vector<io::TimedPose> poses_;
  double tolerance_;
};

}  // namespace

void GtErrorOptions::Validate() const {
  if (!(time_tolerance_s >= 0.0) || !std::isfinite(time_tolerance_s)) {
    throw InputError(fmt::format("time_tolerance_s = {}: must be a finite number of seconds >= 0", time_tolerance_s));
  }
}

GtError ComputeGtError(const std::vector<io::TimedPose>& trajectory, const std::vector<io::Relation>& relations,
                       const GtErrorOptions& options) {
  options.Validate();
  const PoseLookup lookup(trajectory, options.time_tolerance_s);
  GtError result;
  std::vector<double> trans, rot, trans_sq, rot_sq;
  for (const io::Relation& relation : relations) {
    const std::optional<Pose2> a = lookup.Find(relation.t1);
    const std::optional<Pose2> b = lookup.Find(relation.t2);
    if (!a || !b) {
      ++result.relations_missing;
      if (result.missing_examples.size() < options.max_missing_examples) {
        const std::string where = relation.line > 0 ? fmt::format("line {}: ", relation.line) : std::string();
        const std::string what = !a && !b ? fmt::format("t1 {:.6f} and t2 {:.6f}", relation.t1, relation.t2)
                                 : !a     ? fmt::format("t1 {:.6f}", relation.t1)
                                          : fmt::format("t2 {:.6f}", relation.t2);
        result.missing_examples.push_back(where + what + " not in the trajectory");
      }
      continue;
    }
    // Kümmerle et al. 2009 eq. 1-2: err = delta^-1 (+) (pose(t1)^-1 (+) pose(t2)).
    const Pose2 estimated = Between(*a, *b);
    const Pose2 err = Between(relation.delta, estimated);
    const double t = std::hypot(err.x, err.y);
    const double r = RadToDeg(std::fabs(err.theta));
    trans.push_back(t);
    rot.push_back(r);
    trans_sq.push_back(t * t);
    rot_sq.push_back(r * r);
  }
  result.relations_used = trans.size();
  const MeanStd t = Stats(trans), r = Stats(rot), t2 = Stats(trans_sq), r2 = Stats(rot_sq);
  result.trans_mean_m = t.mean;
  result.trans_std_m = t.std;
  result.rot_mean_deg = r.mean;
  result.rot_std_deg = r.std;
  result.trans_sq_mean = t2.mean;
  result.trans_sq_std = t2.std;
  result.rot_sq_mean = r2.mean;
  result.rot_sq_std = r2.std;
  result.trans_max_m =
      trans.empty() ? std::numeric_limits<double>::quiet_NaN() : *std::max_element(trans.begin(), trans.end());
  result.rot_max_deg =
      rot.empty() ? std::numeric_limits<double>::quiet_NaN() : *std::max_element(rot.begin(), rot.end());
  return result;
}

std::vector<std::pair<std::string, double>> GtErrorFields(const GtError& e) {
  return {{"trans_mean_m", e.trans_mean_m},
          {"trans_std_m", e.trans_std_m},
          {"rot_mean_deg", e.rot_mean_deg},
          {"rot_std_deg", e.rot_std_deg},
          {"trans_sq_mean", e.trans_sq_mean},
          {"trans_sq_std", e.trans_sq_std},
          {"rot_sq_mean", e.rot_sq_mean},
          {"rot_sq_std", e.rot_sq_std},
          {"trans_max_m", e.trans_max_m},
          {"rot_max_deg", e.rot_max_deg},
          {"relations_used", static_cast<double>(e.relations_used)},
          {"relations_missing", static_cast<double>(e.relations_missing)}};
}

std::string FormatGtError(const GtError& e) {
  std::string out;
  out += fmt::format("relations used        {}\n", e.relations_used);
  out += fmt::format("relations missing     {}\n", e.relations_missing);
  for (const std::string& example : e.missing_examples) out += fmt::format("  missing             {}\n", example);
  out += fmt::format("translational error   {:.6f} +- {:.6f} m (max {:.6f} m)\n", e.trans_mean_m, e.trans_std_m,
                     e.trans_max_m);
  out += fmt::format("  squared             {:.6f} +- {:.6f} m^2\n", e.trans_sq_mean, e.trans_sq_std);
  out += fmt::format("rotational error      {:.6f} +- {:.6f} deg (max {:.6f} deg)\n", e.rot_mean_deg, e.rot_std_deg,
                     e.rot_max_deg);
  out += fmt::format("  squared             {:.6f} +- {:.6f} deg^2\n", e.rot_sq_mean, e.rot_sq_std);
  return out;
}

}  // namespace slamtune::metrics
