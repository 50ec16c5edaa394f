// Seeded random numbers for the simulator, identical on every platform for a given seed.
//
// Why not std::normal_distribution: its algorithm is left to the standard library, so the
// same seed would give different logs with libstdc++ and libc++. std::mt19937_64 is fully
// specified by the standard; on top of it we draw uniforms from the top 53 bits and normals
// by the Box–Muller transform (Box & Muller 1958, Ann. Math. Statist. 29(2)), both written
// out here so the stream of numbers is fixed by this file alone.
#pragma once

#include <cstdint>
#include <random>

namespace slamtune::sim {

class Random {
 public:
  explicit Random(uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1): the top 53 bits of one 64-bit draw, scaled by 2^-53.
  double Uniform();
  // Standard normal N(0, 1) (Box–Muller; the second value of each pair is kept for the next call).
  double Gaussian();
  // N(0, sigma^2); sigma == 0 still consumes a draw so streams stay aligned whatever the options.
  double Gaussian(double sigma) { return sigma * Gaussian(); }

 private:
  std::mt19937_64 engine_;
  bool has_spare_ = false;
  double spare_ = 0.0;
};

// Seed of an independent stream `stream` derived from the user's `seed` (SplitMix64 mixing,
// Steele, Lea & Flood 2014). Separate streams keep, e.g., the odometry noise unchanged when
// only the laser's beam count changes.
uint64_t StreamSeed(uint64_t seed, uint64_t stream);

}  // namespace slamtune::sim
