// Association and niche-preserving selection of NSGA-III (Deb & Jain 2014, §IV-D, §IV-E).
//
// After normalisation (normalization.h) every survival candidate is associated with the
// reference line (through the origin and a reference point) nearest to it in perpendicular
// distance (Algorithm 3). The members already accepted from the better fronts give each
// reference point a niche count rho_j. The K places left are then filled from the last front
// F_l one at a time (Algorithm 4): take a reference point of least rho_j among those still
// active (ties at random); if F_l has no unselected member associated with it, the point is
// excluded for the rest of this generation; otherwise pick the member nearest to the line
// when rho_j == 0, a random associated member when rho_j >= 1, and increment rho_j.
#pragma once

#include <cstddef>
#include <random>
#include <vector>

namespace slamtune::nsga3 {

// Perpendicular distance from `point` to the line through the origin with direction
// `direction` (non-zero): |point - (w.point / w.w) w|.
double PerpendicularDistance(const std::vector<double>& point, const std::vector<double>& direction);

// Result of associating points with reference lines (Algorithm 3).
struct Association {
  std::vector<std::size_t> reference;  // per point: index of the nearest reference line (lowest on ties)
  std::vector<double> distance;        // per point: its perpendicular distance to that line
};

// Associates each normalised point with its nearest reference line. All vectors share one
// dimension; `reference_points` is non-empty with non-zero directions.
Association Associate(const std::vector<std::vector<double>>& normalized_points,
                      const std::vector<std::vector<double>>& reference_points);

// What the niching step did.
struct NicheSelection {
  std::vector<std::size_t> chosen;       // indices of the selected points, in selection order
  std::vector<std::size_t> niche_count;  // rho_j per reference point after the selection
  std::size_t excluded_references = 0;   // reference points dropped for lack of candidates
};

// Algorithm 4: selects `count` members of `last_front` (indices into `association`, distinct,
// count <= last_front.size()). `niche_count` holds rho_j of the members already accepted
// (one entry per reference point). Randomness (tie breaks, rho_j >= 1 picks) comes from `rng`.
NicheSelection SelectByNiching(std::size_t count, std::vector<std::size_t> niche_count,
                               const std::vector<std::size_t>& last_front, const Association& association,
                               std::mt19937& rng);

}  // namespace slamtune::nsga3
