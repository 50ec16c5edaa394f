// Every scan of a recording that is not mapped, by why, each reason with one name that run.json,
// results.json, `check --json` and the report share (`scans_not_used`), and the lines that say
// it on stderr — with --quiet too: quiet silences progress, never data loss.
//
// The kinds, in the order a scan meets them:
//   no_odometry          no odometric pose at the scan's stamp: tf or odometry missing there,
//                        refused (NaN, inf, a bad rotation), outside its samples or across a gap
//                        longer than --max-odom-gap; a CARMEN RAWLASER scan outside the ODOM
//                        records' time span. Data lost.
//   malformed            undecodable or inconsistent (ranges against angles), skipped with
//                        --lenient. Data lost.
//   cut_off              in the tail of a recording cut off inside a record (not read), or after
//                        the last whole record of a recording without its end marker: how many is
//                        not known (count null), the bytes are. Data lost.
//   wrong_reading_count  the node's Karto laser, made from the first scan, refuses a scan of
//                        another reading count (beam_geometry.h). Data lost, as the node loses it.
//   filtered_by_node     the node's own filter before Karto (slam/node_scan_filter.h: throttle_scans,
//                        the synchronous slam_toolbox node's time, travel and warm-up tests), by
//                        verdict. By design of the node mode.
//   not_moved            Karto's own gate (minimum_travel_distance / _heading): normal thinning.
// The first four are decided by the recording (and the node), the same for every run on it: what
// `check`, `info` and `optimize` report. The last two depend on the parameters: each run's own
// (run.json, slam/log_runner.h RunLosses).
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/io/beam_geometry.h"
#include "slamtune/io/laser_log.h"

namespace slamtune::io {

enum class ScanLossKind { kNoOdometry, kMalformed, kCutOff, kWrongReadingCount, kFilteredByNode, kNotMoved };
inline constexpr int kNumScanLossKinds = 6;
// "no_odometry", "malformed", "cut_off", "wrong_reading_count", "filtered_by_node", "not_moved".
const char* NameOf(ScanLossKind kind);
// What scans of this kind are, in general, one clause (for outputs that list every kind).
const char* DescriptionOf(ScanLossKind kind);
// Whether scans of this kind are data the user recorded and does not get mapped (all but the
// node's filter and Karto's travel gate, which are what the node does by design).
bool IsDataLoss(ScanLossKind kind);

struct ScanLoss {
  ScanLossKind kind = ScanLossKind::kNoOdometry;
  std::optional<std::size_t> count;       // scans; none when they cannot be counted (cut_off)
  std::uint64_t bytes = 0;                // cut_off: bytes of the recording not read
  std::string why;                        // what happened to them and what to do, one clause
  std::string first;                      // the first one, e.g. "scan 40 at 104.025000 s: ..."; may be empty
  std::map<std::string, std::size_t> by;  // filtered_by_node: by verdict; wrong_reading_count: by node
  // Whether anything of this kind happened.
  bool happened() const { return !count || *count > 0; }
};

struct ScanLosses {
  std::vector<ScanLoss> kinds;  // in ScanLossKind order; those that happened and those that did not

  const ScanLoss* Find(ScanLossKind kind) const;
  ScanLoss& Get(ScanLossKind kind);  // adds the kind (count 0) when absent, keeping the order
  // Scans not used in all (kinds whose count is known).
  std::size_t counted() const;
  // One line per kind that happened and is data loss, e.g. "not used: 11 scans without odometry
  // at their stamp (first: ...)": what every command prints, --quiet or not.
  std::vector<std::string> LossLines() const;
};

// The kinds the recording decides (no_odometry, malformed, cut_off, wrong_reading_count). For
// wrong_reading_count, `rule` names the node whose laser the engine models (its count then; by
// node as well), or none (the larger of the two nodes' counts, and both by node).
ScanLosses ReadingLosses(const LaserLog& log, std::optional<KartoLaserRule> rule = std::nullopt);

}  // namespace slamtune::io
