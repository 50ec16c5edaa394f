// Relation-based error of an estimated trajectory against ground-truth relations (Kümmerle et
// al. 2009, "On measuring the accuracy of SLAM algorithms", Auton. Robots 27:397-407, §3,
// eq. 1-2), the number the Freiburg benchmark reports for each dataset.
//
// Convention (metrics::ComputeGtError): for each relation (t1, t2, delta) the estimated poses
// at t1 and t2 are looked up by timestamp (match within GtErrorOptions::time_tolerance_s: the
// mit-csail relations have 5 decimals, the log 6); the estimated relative pose is
// e = Between(pose(t1), pose(t2)) and the error is err = Between(delta, e) = delta^-1 (+) e.
// Translational error |err.xy| (m), rotational error |err.theta| (deg). Reported: mean and
// sample standard deviation (n - 1 divisor) of both and of their squares (m^2, deg^2).
// Relations whose timestamps are not in the trajectory are counted and the first few named,
// never silently dropped.
#pragma once

#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "slamtune/io/relations.h"
#include "slamtune/io/trajectory.h"

namespace slamtune::metrics {

struct GtErrorOptions {
  double time_tolerance_s = 1e-5;        // s; a pose matches a relation timestamp within this
  std::size_t max_missing_examples = 5;  // relations with unknown timestamps named in the result

  // Throws InputError naming the field if time_tolerance_s is negative or not finite.
  void Validate() const;
};

struct GtError {
  // Statistics over the relations used; NaN when none was used. The standard deviations are 0
  // when exactly one relation was used.
  double trans_mean_m = 0.0;
  double trans_std_m = 0.0;
  double rot_mean_deg = 0.0;
  double rot_std_deg = 0.0;
  double trans_sq_mean = 0.0;  // m^2
  double trans_sq_std = 0.0;   // m^2
  double rot_sq_mean = 0.0;    // deg^2
  double rot_sq_std = 0.0;     // deg^2
  double trans_max_m = 0.0;
  double rot_max_deg = 0.0;
  std::size_t relations_used = 0;
  // Relations with a timestamp not found in the trajectory (within the tolerance).
  std::size_t relations_missing = 0;
  // The first few of them: "line L: t1 T not in the trajectory" (t2, or both).
  std::vector<std::string> missing_examples;
};

GtError ComputeGtError(const std::vector<io::TimedPose>& trajectory, const std::vector<io::Relation>& relations,
                       const GtErrorOptions& options = {});

// The numeric fields of `error` in a fixed order, named as the JSON keys of `slamtune gt-error`
// (trans_mean_m, trans_std_m, ...); NaN stays NaN (the CLI writes null).
std::vector<std::pair<std::string, double>> GtErrorFields(const GtError& error);

// Human-readable multi-line summary.
std::string FormatGtError(const GtError& error);

}  // namespace slamtune::metrics
