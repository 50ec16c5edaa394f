// Inverted generational distance (IGD) and the targeted Pareto-optimal points it is measured
// against, as in Deb & Jain 2014, §VI-A (eq. 6).
//
// IGD(A, Z) = (1/|Z|) sum_{z in Z} min_{a in A} |z - a|: the mean distance from each target
// z to the nearest obtained point. It rewards both convergence and spread over the targets.
// NSGA-III aims at the points where the reference directions meet the true front, so the
// paper measures IGD against exactly those: for DTLZ1's linear front sum f = 1/2 they are
// w * 0.5 / sum(w), for the spherical fronts of DTLZ2-4 (|f| = 1) they are w / |w|.
#pragma once

#include <vector>

namespace slamtune::nsga3 {

// IGD of `obtained` against `targets` (both non-empty, one common dimension).
double InvertedGenerationalDistance(const std::vector<std::vector<double>>& targets,
                                    const std::vector<std::vector<double>>& obtained);

// Where each direction (non-negative, non-zero) meets the hyperplane sum(f) = `sum`.
std::vector<std::vector<double>> TargetsOnSimplex(const std::vector<std::vector<double>>& directions, double sum);

// Where each direction (non-zero) meets the unit sphere |f| = 1.
std::vector<std::vector<double>> TargetsOnUnitSphere(const std::vector<std::vector<double>>& directions);

}  // namespace slamtune::nsga3
