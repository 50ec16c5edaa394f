// Bit-for-bit equality of numbers and poses, for tests that hold an exact speed-up or a cache to
// giving the very bits of the plain computation (CONTRIBUTING.md, "Test"). Unlike ==, 0.0 and -0.0
// differ and a NaN equals a NaN with the same bits.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "slamtune/common/pose2.h"

namespace slamtune::testing {

inline bool SameBits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

inline bool SameBits(const Pose2& a, const Pose2& b) {
  return SameBits(a.x, b.x) && SameBits(a.y, b.y) && SameBits(a.theta, b.theta);
}

inline bool SameBits(const std::vector<Pose2>& a, const std::vector<Pose2>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t k = 0; k < a.size(); ++k) {
    if (!SameBits(a[k], b[k])) return false;
  }
  return true;
}

}  // namespace slamtune::testing
