// Reference points of NSGA-III (Deb & Jain, IEEE TEC 18(4), 2014, §IV-B and §V-B).
//
// NSGA-III keeps diversity by spreading the population over a set of reference directions
// on the unit simplex {w >= 0, sum(w) = 1}. The default is Das and Dennis' structured grid:
// every w whose components are multiples of 1/D, which gives H = C(M + D - 1, D) points
// (eq. 3 of the paper; M = 3, D = 12 -> 91). For many objectives the paper (§V-B) uses two
// layers: a boundary grid with D1 divisions and an inside grid with D2 divisions shrunk
// halfway towards the centroid, w_in = (w + 1/M) / 2.
//
// A caller may instead supply its own reference points (preferred directions, §VI of the
// paper); ValidateReferencePoints says what they must satisfy. The grid itself comes from
// pagmo::decomposition_weights(..., "grid", ...), which takes the number of points, so the
// count is computed here first.
#pragma once

#include <cstddef>
#include <vector>

namespace slamtune::nsga3 {

using ReferencePoints = std::vector<std::vector<double>>;

// H = C(M + D - 1, D): number of Das-Dennis points for `objectives` M >= 2 and `divisions`
// D >= 1. Throws InputError on M < 2, D < 1 or a count that would not fit in 32 bits.
std::size_t DasDennisCount(std::size_t objectives, std::size_t divisions);

// The Das-Dennis grid on the unit simplex: DasDennisCount(M, D) points of dimension M,
// components k / D. Order as produced by pagmo (deterministic, no randomness involved).
ReferencePoints DasDennisPoints(std::size_t objectives, std::size_t divisions);

// Two-layer set of §V-B: the boundary grid (D = `boundary_divisions`) followed by the inside
// grid (D = `inner_divisions`) mapped to (w + 1/M) / 2. `inner_divisions` == 0 gives the
// boundary grid alone.
ReferencePoints LayeredReferencePoints(std::size_t objectives, std::size_t boundary_divisions,
                                       std::size_t inner_divisions);

// Checks user-supplied reference points: at least one point, each of dimension `objectives`,
// every component finite and >= 0, and a positive sum (a direction must exist). Points need
// not lie on the simplex: association (niching.h) uses only their direction. Throws
// InputError naming `field`, the offending point index and the rule.
void ValidateReferencePoints(const ReferencePoints& points, std::size_t objectives, const char* field);

}  // namespace slamtune::nsga3
