// The processed scans of each laser (docs/engine.md §3.1, §3.5). Karto's mapper keeps, per
// laser, the list of its processed scans, numbered 0, 1, 2, ... within that laser (its state
// ids), beside one numbering over all lasers (its unique ids). The engine's state ids are the
// second kind (indices into Mapper::scans()); this records which laser each one belongs to and
// its place in that laser's list, because "consecutive scans" in the near-chain walk (§5.4)
// and the loop-candidate walk (§6.2) are consecutive scans of one laser. With one laser every
// list is the identity: scans_of(0) is 0, 1, 2, ...
#pragma once

#include <span>
#include <vector>

namespace slamtune::slam {

class ScansByLaser {
 public:
  // Registers state id size() as the next scan of `laser` (0 <= laser < kMaxLasers).
  void Add(int laser);
  static constexpr int kMaxLasers = 1 << 16;

  int size() const { return static_cast<int>(laser_of_.size()); }
  // Lasers seen so far: 1 + the largest laser index added (a laser may have no scans).
  int num_lasers() const { return static_cast<int>(lists_.size()); }
  int laser_of(int id) const { return laser_of_[id]; }
  // Index of `id` in scans_of(laser_of(id)): Karto's per-laser state id.
  int position(int id) const { return position_[id]; }
  // The state ids of `laser`'s scans in processing order; empty for a laser without any.
  std::span<const int> scans_of(int laser) const;

  friend bool operator==(const ScansByLaser&, const ScansByLaser&) = default;

 private:
  std::vector<std::vector<int>> lists_;
  std::vector<int> laser_of_;
  std::vector<int> position_;
};

}  // namespace slamtune::slam
