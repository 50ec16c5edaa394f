#include "slamtune/io/scan_losses.h"

#include <fmt/format.h>

#include <algorithm>

namespace slamtune::io {

const char* NameOf(ScanLossKind kind) {
  switch (kind) {
    case ScanLossKind::kNoOdometry: return "no_odometry";
    case ScanLossKind::kMalformed: return "malformed";
    case ScanLossKind::kCutOff: return "cut_off";
    case ScanLossKind::kWrongReadingCount: return "wrong_reading_count";
    case ScanLossKind::kFilteredByNode: return "filtered_by_node";
    case ScanLossKind::kNotMoved: return "not_moved";
  }
  return "unknown";
}

const char* DescriptionOf(ScanLossKind kind) {
  switch (kind) {
    case ScanLossKind::kNoOdometry:
      return "scans without an odometric pose at their stamp (tf or odometry missing, refused, outside its samples "
             "or across a gap)";
    case ScanLossKind::kMalformed: return "undecodable or inconsistent scans, skipped (--lenient)";
    case ScanLossKind::kCutOff: return "scans after the last whole record of a recording cut off (not counted)";
    case ScanLossKind::kWrongReadingCount:
      return "scans whose reading count differs from what the node's Karto laser expects: the node drops them";
    case ScanLossKind::kFilteredByNode:
      return "scans the node does not hand to Karto (throttle_scans; the synchronous slam_toolbox node's filter)";
    case ScanLossKind::kNotMoved:
      return "scans Karto skips because the robot moved less than minimum_travel_distance and "
             "minimum_travel_heading (normal thinning)";
  }
  return "";
}

bool IsDataLoss(ScanLossKind kind) { return kind != ScanLossKind::kFilteredByNode && kind != ScanLossKind::kNotMoved; }

const ScanLoss* ScanLosses::Find(ScanLossKind kind) const {
  for (const ScanLoss& k : kinds) {
    if (k.kind == kind) return &k;
  }
  return nullptr;
}

ScanLoss& ScanLosses::Get(ScanLossKind kind) {
  auto it = std::find_if(kinds.begin(), kinds.end(), [&](const ScanLoss& k) { return k.kind >= kind; });
  if (it != kinds.end() && it->kind == kind) return *it;
  ScanLoss added;
  added.kind = kind;
  added.count = 0;
  return *kinds.insert(it, added);
}

std::size_t ScanLosses::counted() const {
  std::size_t n = 0;
  for (const ScanLoss& k : kinds) n += k.count.value_or(0);
  return n;
}

std::vector<std::string> ScanLosses::LossLines() const {
  std::vector<std::string> out;
  for (const ScanLoss& k : kinds) {
    if (!IsDataLoss(k.kind) || !k.happened()) continue;
    const std::string first = k.first.empty() ? "" : " (first: " + k.first + ")";
    out.push_back(k.count ? fmt::format("not used: {} {}{}", *k.count, k.why, first)
                          : fmt::format("not used: {}{}", k.why, first));
  }
  return out;
}

ScanLosses ReadingLosses(const LaserLog& log, std::optional<KartoLaserRule> rule) {
  ScanLosses out;
  const RecordingInfo* r = log.recording ? &*log.recording : nullptr;

  ScanLoss& odometry = out.Get(ScanLossKind::kNoOdometry);
  if (r != nullptr && r->scans_unplaced > 0) {
    odometry.count = r->scans_unplaced;
    odometry.why = "scans without odometry at their stamp";
    if (r->tf_bad_rotations + r->tf_refused_frames > 0) {
      odometry.why += fmt::format(" ({} tf transforms refused: NaN, inf or a bad rotation, or a bad frame id)",
                                  r->tf_bad_rotations + r->tf_refused_frames);
    }
    if (!r->unplaced_examples.empty()) odometry.first = r->unplaced_examples.front();
  } else if (log.scans_without_odometry > 0) {
    odometry.count = log.scans_without_odometry;
    odometry.why = "RAWLASER scans outside the time span of the ODOM records, no pose to interpolate";
    odometry.first = log.first_scan_without_odometry;
  }

  ScanLoss& malformed = out.Get(ScanLossKind::kMalformed);
  if (r != nullptr && r->scans_malformed > 0) {
    malformed.count = r->scans_malformed;
    malformed.why = "malformed scans, skipped (--lenient)";
    if (!r->malformed_examples.empty()) malformed.first = r->malformed_examples.front();
  } else if (log.skipped_scans > 0) {
    malformed.count = log.skipped_scans;
    malformed.why = "malformed laser records, skipped (--lenient)";
    malformed.first = log.first_skipped_scan;
  }

  ScanLoss& cut = out.Get(ScanLossKind::kCutOff);
  if (r != nullptr && r->data_end.dropped_bytes > 0) {
    cut.count.reset();
    cut.bytes = r->data_end.dropped_bytes;
    cut.why = fmt::format("the scans in the last {} bytes of the recording (how many is not known): {}",
                          r->data_end.dropped_bytes, r->data_end.how);
  } else if (r != nullptr && !r->data_end.complete) {
    cut.count.reset();
    cut.why = fmt::format(
        "whatever was recorded after the file's end: it ends without its end marker ({}), "
        "read up to there",
        r->data_end.how);
  }

  ScanLoss& readings = out.Get(ScanLossKind::kWrongReadingCount);
  const BeamReport& b = log.beams;
  readings.by = {{"slam_karto", b.slam_karto.dropped}, {"slam_toolbox", b.slam_toolbox.dropped}};
  const bool engine_keeps =
      b.policy == BeamPolicyName(BeamPolicy::kPerGeometry) || b.policy == BeamPolicyName(BeamPolicy::kNearestBeam);
  const std::size_t dropped = !rule ? std::max(b.slam_karto.dropped, b.slam_toolbox.dropped)
                              : *rule == KartoLaserRule::kSlamKarto ? b.slam_karto.dropped
                                                                    : b.slam_toolbox.dropped;
  readings.count = engine_keeps ? 0 : dropped;
  readings.why = rule ? fmt::format(
                            "scans whose reading count differs from what {}'s Karto laser expects: the node "
                            "drops them (make the driver publish a fixed count)",
                            *rule == KartoLaserRule::kSlamKarto ? "slam_karto" : "slam_toolbox")
                      : "scans whose reading count differs from what the node's Karto laser expects: the node drops "
                        "them (make the driver publish a fixed count)";
  return out;
}

}  // namespace slamtune::io
