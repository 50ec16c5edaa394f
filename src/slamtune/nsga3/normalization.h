// Adaptive normalisation of objective vectors for NSGA-III (Deb & Jain 2014, §IV-C).
//
// Reference points live on the unit simplex, so the objectives must be brought to a common
// scale before association, otherwise an objective measured in larger units would dominate
// the distances. The paper's procedure, applied each generation to the survival candidates
// S_t:
//   1. ideal point z_min: the per-objective minimum over S_t and all earlier generations
//      (the union of S_tau, tau = 0..t; the caller carries the earlier minimum);
//   2. extreme point of axis j: the member minimising the achievement scalarising function
//      ASF(f, w_j) = max_i (f_i - z_min_i) / w_ji with w_j = e_j and 1e-6 off the axis (eq. 4);
//   3. intercepts a_j of the hyperplane through the M translated extreme points;
//   4. normalised objectives f_n = (f - z_min) / a (eq. 5).
//
// The paper leaves the degenerate hyperplane open. Here the nadir is kept in absolute
// coordinates, nadir = z_min + a, and the hyperplane is rejected when extreme points
// coincide or are collinear (singular system), when the solve is inaccurate, or when an
// intercept is NaN, infinite or not above `min_intercept`; the nadir is then the worst point
// of the first front. Any objective whose range nadir - z_min is still <= min_intercept takes
// the worst value over all of S_t, and a range that is still zero (the objective is constant
// over S_t) is set to 1. Every path normalises as (f - z_min) / (nadir - z_min).
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace slamtune::nsga3 {

struct NormalizationOptions {
  // Off-axis weight of the ASF used to find the extreme points (eq. 4); dimensionless, > 0
  // and < 1. The paper's value is 1e-6.
  double asf_off_axis_weight = 1e-6;
  // Smallest acceptable intercept (nadir - ideal) per objective, in objective units; smaller
  // (or non-positive) intercepts reject the hyperplane. >= 0.
  double min_intercept = 1e-6;

  // Throws InputError naming the field, its value and the rule.
  void Validate() const;
};

// Where the nadir value of one objective came from.
enum class NadirSource {
  kHyperplane,       // intercept of the hyperplane through the extreme points (§IV-C)
  kFrontWorst,       // hyperplane rejected: worst value over the first non-dominated front
  kCandidatesWorst,  // range still <= min_intercept: worst value over all candidates
  kUnitRange,        // objective constant over the candidates: nadir = ideal + 1
};

const char* ToString(NadirSource source);

// What the normalisation found and why (one per survival step).
struct Normalization {
  std::vector<double> ideal;                // z_min, absolute objective units
  std::vector<double> nadir;                // absolute objective units, > ideal on every axis
  std::vector<std::size_t> extreme_points;  // index (into the candidates) of the extreme point per axis
  std::vector<NadirSource> nadir_source;    // per objective
  std::string hyperplane_rejection;         // empty when the hyperplane was used, else the reason

  // (f - ideal) / (nadir - ideal), eq. 5.
  std::vector<double> Normalize(const std::vector<double>& f) const;
  std::vector<std::vector<double>> NormalizeAll(const std::vector<std::vector<double>>& points) const;
};

// Computes the normalisation of `candidates` (objective vectors, all of the same dimension
// M >= 1, finite) given the indices of their first non-dominated front `first_front`
// (non-empty, indices into `candidates`). The ideal point is the per-objective minimum of the
// candidates and of `earlier_ideal` (the ideal of earlier generations, M values, or empty
// when there is none). `options` must be valid.
Normalization ComputeNormalization(const std::vector<std::vector<double>>& candidates,
                                   const std::vector<std::size_t>& first_front, const NormalizationOptions& options,
                                   const std::vector<double>& earlier_ideal = {});

}  // namespace slamtune::nsga3
