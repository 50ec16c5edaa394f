// Numeric conventions of Karto that change decisions (docs/engine.md §1.1–1.3).
//
// Karto rounds half away from zero, compares with a 1e-6 tolerance and maps angles into
// [-pi, pi] by whole turns. Using std::round or fmod variants instead changes which cell
// a point falls in, and so which loop closures fire; keep every caller on these helpers.
#pragma once

#include <cmath>
#include <cstdint>

namespace slamtune {

// Tolerance of almost every Karto comparison (§1.1).
inline constexpr double kKartoTolerance = 1e-6;
inline constexpr double kPi = 3.14159265358979323846;
inline constexpr double kTwoPi = 2.0 * kPi;
// Karto's degree->radian factor, written as its literal so that 20 degrees (response
// expansion, §4.2 item 5) has Karto's exact bits.
inline constexpr double kRadiansPerDegree = 0.01745329251994329577;

// Round half away from zero (§1.2): floor(v + 0.5) for v >= 0, ceil(v - 0.5) otherwise.
inline double KartoRound(double v) { return v >= 0.0 ? std::floor(v + 0.5) : std::ceil(v - 0.5); }

// KartoRound cast to a 32-bit int, as Karto's world->grid conversion does.
inline int32_t KartoRoundToInt(double v) { return static_cast<int32_t>(KartoRound(v)); }

// |a - b| <= 1e-6 (§1.2).
inline bool KartoEqual(double a, double b) { return std::fabs(a - b) <= kKartoTolerance; }

// Karto's whole-turn loops below serve every angle a robot produces; an angle beyond this many
// radians (only corrupt input gives one) is first brought near by std::remainder, because the
// loops would take millions of turns, or forever where subtracting 2 pi no longer changes the
// double. An infinite angle becomes NaN.
inline constexpr double kTurnLoopLimit = 64.0 * kTwoPi;

// Maps an angle into [-pi, pi] by adding or subtracting whole turns; values already inside
// (including +-pi) are returned unchanged (§1.3).
inline double NormalizeAngle(double a) {
  if (std::fabs(a) > kTurnLoopLimit) a = std::remainder(a, kTwoPi);
  while (a < -kPi) a += kTwoPi;
  while (a > kPi) a -= kTwoPi;
  return a;
}

// Shifts `a` by whole turns until a - ref lies in [-pi, pi]; returns the shifted a (§1.3).
inline double NormalizeAngleDifference(double a, double ref) {
  if (std::fabs(a - ref) > kTurnLoopLimit) a = ref + std::remainder(a - ref, kTwoPi);
  while (a - ref > kPi) a -= kTwoPi;
  while (a - ref < -kPi) a += kTwoPi;
  return a;
}

inline double DegToRad(double deg) { return deg * kPi / 180.0; }
inline double RadToDeg(double rad) { return rad * 180.0 / kPi; }

}  // namespace slamtune
