#include "slamtune/io/check/log_check.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <utility>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"
#include "slamtune/io/beam_geometry.h"
#include "slamtune/io/check/check_problems.h"
#include "slamtune/io/check/odometry_check.h"
#include "slamtune/io/log_reader.h"
#include "slamtune/io/log_summary.h"
#include "slamtune/io/ros/recording_contents.h"
#include "slamtune/io/ros/recording_log.h"
#include "slamtune/io/ros/ros_recording.h"

namespace slamtune::io {
namespace {

void Problem(CheckReport* report, ProblemKind kind, std::string what, std::size_t count = 1) {
  report->problems.push_back({kind, std::move(what), count, {}, {}});
}

void CheckStamps(const std::vector<double>& stamps, const CheckOptions& o, CheckReport* report) {
  std::vector<double> periods;
  for (std::size_t k = 1; k < stamps.size(); ++k) {
    if (stamps[k] > stamps[k - 1]) periods.push_back(stamps[k] - stamps[k - 1]);
  }
  const double period = MedianOf(periods);
  if (period > 0)
    report->facts.push_back(fmt::format("scan period: {:.4f} s median ({:.2f} Hz)", period, 1.0 / period));
  ProblemOccurrences gaps, back, duplicate;
  double longest = 0.0, largest_back = 0.0;
  for (std::size_t k = 1; k < stamps.size(); ++k) {
    const double dt = stamps[k] - stamps[k - 1];
    if (dt < 0) {
      back.Add(k, stamps[k]);
      largest_back = std::max(largest_back, -dt);
    } else if (dt == 0) {
      duplicate.Add(k, stamps[k]);
    } else if (period > 0 && dt > o.gap_factor * period) {
      gaps.Add(k, stamps[k]);
      longest = std::max(longest, dt);
    }
  }
  ReportOccurrences(report, ProblemKind::kScanGap, gaps,
                    fmt::format("{} gaps between scan stamps longer than {} x the median period (longest {:.3f} s)",
                                gaps.count, o.gap_factor, longest));
  ReportOccurrences(
      report, ProblemKind::kScanStampBackward, back,
      fmt::format("{} scan stamps earlier than the one before (largest step back {:.3f} s)", back.count, largest_back));
  ReportOccurrences(report, ProblemKind::kScanStampDuplicate, duplicate,
                    fmt::format("{} scans with the same stamp as the one before", duplicate.count));
}

void CheckBeams(const LaserLog& log, CheckReport* report) {
  if (log.scans.empty()) return;
  report->facts.push_back("beams: " + GeometryOf(log.scans.front()).ToString());
  ProblemOccurrences changes;
  for (std::size_t k = 1; k < log.scans.size(); ++k) {
    if (!GeometryOf(log.scans[k]).SameAs(GeometryOf(log.scans[k - 1]), kSameAngleTolerance)) {
      changes.Add(k, log.scans[k].ipc_time);
    }
  }
  std::string seen;
  for (const BeamReport::Seen& g : log.beams.geometries) {
    seen += fmt::format("{}{} in {} scans", seen.empty() ? "" : "; ", g.geometry.ToString(), g.scans);
  }
  const std::size_t first = log.scans.front().ranges.size();
  std::size_t dropped = 0;
  for (auto [node, rule] :
       {std::pair{"slam_karto", KartoLaserRule::kSlamKarto}, std::pair{"slam_toolbox", KartoLaserRule::kSlamToolbox}}) {
    const std::size_t expected = ExpectedReadings(rule, log.scans.front());
    const auto refused = static_cast<std::size_t>(std::count_if(
        log.scans.begin(), log.scans.end(), [&](const LaserScanRecord& s) { return s.ranges.size() != expected; }));
    if (rule == KartoLaserRule::kSlamToolbox) dropped = refused;
    if (expected == first) continue;
    report->problems.push_back(
        {ProblemKind::kLaserCountMismatch,
         fmt::format("{} drops {} of {} scans: the Karto laser it makes from the first scan expects {} readings (from "
                     "angle_min, angle_max and angle_increment) and the first scan has {}; the driver's angles and "
                     "reading count disagree for that node",
                     node, refused, log.scans.size(), expected, first),
         refused,
         {0},
         {log.scans.front().ipc_time}});
  }
  ReportOccurrences(
      report, ProblemKind::kBeamGeometryChange, changes,
      fmt::format("the beam geometry changes {} times between scans ({}); the node drops the {} of {} scans whose "
                  "beam count differs from the first scan's, and so does slamtune: make the driver publish a fixed "
                  "count (or tune with --beams per-geometry, which the node does not do)",
                  changes.count, seen, dropped, log.scans.size()));
}

void CheckRanges(const LaserLog& log, const CheckOptions& o, CheckReport* report) {
  ProblemOccurrences above;
  double largest_valid = 0.0, largest_above = 0.0, range_max = 0.0;
  std::size_t readings = 0, no_returns = 0, above_count = 0;
  for (std::size_t k = 0; k < log.scans.size(); ++k) {
    const LaserScanRecord& scan = log.scans[k];
    range_max = std::max(range_max, scan.max_range);
    std::size_t scan_above = 0;
    for (double r : scan.ranges) {
      if (!std::isfinite(r) || r < 0) continue;
      if (r > scan.max_range * (1 + 1e-6)) {
        ++scan_above;
        largest_above = std::max(largest_above, r);
      } else if (r < scan.max_range) {
        largest_valid = std::max(largest_valid, r);
      }
    }
    if (scan_above > 0) above.Add(k, scan.ipc_time);
    above_count += scan_above;
    readings += scan.ranges.size();
    no_returns += scan.no_returns;
  }
  const double share = readings > 0 ? static_cast<double>(no_returns) / static_cast<double>(readings) : 0.0;
  report->facts.push_back(
      fmt::format("readings: {}, largest below range_max {:.3f} m, range_max {} m, no-returns "
                  "{:.1f} %",
                  readings, largest_valid, range_max, 100.0 * share));
  if (above.count > 0) {
    report->problems.push_back(
        {ProblemKind::kRangeMaxTooLow,
         fmt::format("{} readings in {} scans lie above range_max (up to {:.3f} m): range_max is too low for this "
                     "laser; they are taken as no-returns",
                     above_count, above.count, largest_above),
         above.count, above.scans, above.times});
  }
  const bool no_range = readings > 0 && CountRanges(log) == 0;
  // Without a single range, "no reading reaches range_max" says nothing more than no_valid_reading.
  if (!no_range && std::isfinite(range_max) && range_max > 0 && largest_valid < o.range_max_use_fraction * range_max) {
    Problem(report, ProblemKind::kRangeMaxTooHigh,
            fmt::format("no reading reaches {:.0f} % of range_max: the largest is {:.3f} m, range_max {} m; if the "
                        "laser's real range is lower, readings at its limit may be taken for walls",
                        100.0 * o.range_max_use_fraction, largest_valid, range_max));
  }
  if (no_range) {
    Problem(report, ProblemKind::kNoValidReading,
            fmt::format("not one of the {} readings of the {} scans is a range (each is inf, NaN, negative, at or "
                        "above range_max or at or below range_min): a map would be empty; run and optimize refuse it",
                        readings, log.scans.size()));
  }
  if (share > o.no_return_majority) {
    Problem(report, ProblemKind::kMostlyNoReturns,
            fmt::format("{:.1f} % of the readings are no-returns (inf, NaN or >= range_max)", 100.0 * share));
  }
}

void CheckRecordingInfo(const LaserLog& log, CheckReport* report) {
  if (!log.recording) return;
  const RecordingInfo& r = *log.recording;
  for (const RecordingInfo::Topic& t : r.topics) {
    report->facts.push_back(
        fmt::format("topic: {} ({}), {} messages, {:.2f} Hz", t.name, t.type, t.messages, t.rate_hz));
  }
  for (const std::string& e : r.tf_edges) report->facts.push_back("tf: " + e);
  if (r.scans_unplaced > 0) {
    Problem(
        report, ProblemKind::kTfMissing,
        fmt::format("{} of {} scans have no odometry at their stamp and cannot be used (first: {})", r.scans_unplaced,
                    r.scan_messages, r.unplaced_examples.empty() ? "-" : r.unplaced_examples.front()),
        r.scans_unplaced);
  }
  if (r.scans_bad_range_max > 0) {
    Problem(report, ProblemKind::kBadRangeMax,
            fmt::format("LaserScan range_max is NaN, infinite, 0 or negative in {} of {} scans (first: {}): {}",
                        r.scans_bad_range_max, r.scan_messages, r.bad_range_max_example, kBadRangeMaxRule),
            r.scans_bad_range_max);
  }
  if (r.scans_malformed + r.messages_undecodable > 0) {
    Problem(report, ProblemKind::kMalformedMessages,
            fmt::format("{} malformed scans and {} undecodable tf / odometry messages (first: {})", r.scans_malformed,
                        r.messages_undecodable, r.malformed_examples.empty() ? "-" : r.malformed_examples.front()),
            r.scans_malformed + r.messages_undecodable);
  }
  if (r.data_end.dropped_bytes > 0) {
    Problem(report, ProblemKind::kTruncatedRecording,
            fmt::format("the recording ends in a corrupt or truncated part: {} bytes not read ({})",
                        r.data_end.dropped_bytes, r.data_end.dropped_reason));
  }
  for (const std::string& loop : r.tf_loops) {
    Problem(report, ProblemKind::kTfLoop,
            fmt::format("the tf tree has a loop, {} (not on the frames used here): tf2 refuses every lookup through "
                        "it",
                        loop));
  }
  if (r.tf_parent_conflicts + r.tf_bad_rotations + r.tf_refused_frames > 0) {
    report->facts.push_back(
        fmt::format("tf: {} transforms ignored (second parent), {} refused (bad rotation or "
                    "translation), {} refused (a frame its own parent, or no frame id)",
                    r.tf_parent_conflicts, r.tf_bad_rotations, r.tf_refused_frames));
  }
}

// Odometry received long after the scan it places: a live slam_toolbox would drop such scans.
void CheckLateness(const RecordingContents& contents, const LaserLog& log, const CheckOptions& o, CheckReport* report) {
  const RecordingInfo& info = *log.recording;
  std::vector<std::int64_t> stamps, received;
  if (info.odometry_source.rfind("tf ", 0) == 0) {
    stamps = contents.tf.SampleStamps(info.base_frame);
    received = contents.tf.SampleReceiveTimes(info.base_frame);
  } else {
    for (const auto& [name, samples] : contents.odometry) {
      if (info.odometry_source.find(name + " ") == std::string::npos) continue;
      for (const OdometrySample& s : samples) {
        stamps.push_back(s.stamp_ns);
        received.push_back(s.log_time_ns);
      }
    }
  }
  if (stamps.empty()) return;
  const auto& scans = contents.scans.at(info.scan_topic);
  ProblemOccurrences late;
  double latest = 0.0;
  for (std::size_t k = 0; k < scans.size(); ++k) {
    const std::int64_t stamp = scans[k].message.header.stamp_ns;
    const auto it = std::lower_bound(stamps.begin(), stamps.end(), stamp);
    if (it == stamps.end()) continue;
    const double delay = static_cast<double>(received[it - stamps.begin()] - scans[k].log_time_ns) / 1e9;
    if (delay > o.late_s) {
      late.Add(k, static_cast<double>(stamp) / 1e9);
      latest = std::max(latest, delay);
    }
  }
  ReportOccurrences(
      report, ProblemKind::kTfLate, late,
      fmt::format("for {} scans the odometry at their stamp was received more than {} s after the scan (up to "
                  "{:.3f} s): a live SLAM node waiting for tf would drop them",
                  late.count, o.late_s, latest));
}

void AddInputFacts(const LaserLog& log, CheckReport* report) {
  for (const std::string& line : DescribeLogInput(log)) {
    if (line.rfind("beams:", 0) != 0) report->facts.push_back(line);
  }
  if (!log.scans.empty()) {
    report->facts.push_back(fmt::format("scans: {} over {:.3f} s, no-return value {} m ({})", log.scans.size(),
                                        log.scans.back().ipc_time - log.scans.front().ipc_time, log.no_return_value,
                                        log.no_return_rule));
  }
}

// Every log check, with stamp checks on `stamps` (all scans, placed or not).
CheckReport CheckParts(const LaserLog& log, const std::vector<double>& stamps, const CheckOptions& options) {
  CheckReport report;
  report.path = log.path;
  report.scans_not_used = ReadingLosses(log);
  AddInputFacts(log, &report);
  CheckStamps(stamps, options, &report);
  CheckBeams(log, &report);
  CheckRanges(log, options, &report);
  CheckOdometry(log, options, &report);
  CheckRecordingInfo(log, &report);
  return report;
}

std::vector<double> StampsOf(const LaserLog& log) {
  std::vector<double> out;
  for (const LaserScanRecord& s : log.scans) out.push_back(s.ipc_time);
  return out;
}

}  // namespace

void CheckOptions::Validate() const {
  const auto require = [](const char* name, double v, double lo, double hi) {
    if (!(v > lo && v <= hi)) throw InputError(fmt::format("check {} = {}: must be in ({}, {}]", name, v, lo, hi));
  };
  require("gap_factor", gap_factor, 1.0, 1000.0);
  require("range_max_use_fraction", range_max_use_fraction, 0.0, 1.0);
  require("no_return_majority", no_return_majority, 0.0, 1.0);
  require("max_speed_mps", max_speed_mps, 0.0, 100.0);
  require("max_turn_rate_rad_s", max_turn_rate_rad_s, 0.0, 100.0);
  require("stall_s", stall_s, 0.0, 3600.0);
  require("moving_speed_mps", moving_speed_mps, 0.0, 10.0);
  require("late_s", late_s, 0.0, 3600.0);
  require("velocity_mismatch_share", velocity_mismatch_share, 0.0, 1.0);
}

const char* ProblemKindName(ProblemKind kind) {
  switch (kind) {
    case ProblemKind::kScanGap: return "scan_gap";
    case ProblemKind::kScanStampBackward: return "scan_stamp_backward";
    case ProblemKind::kScanStampDuplicate: return "scan_stamp_duplicate";
    case ProblemKind::kBeamGeometryChange: return "beam_geometry_change";
    case ProblemKind::kLaserCountMismatch: return "laser_count_mismatch";
    case ProblemKind::kRangeMaxTooLow: return "range_max_too_low";
    case ProblemKind::kRangeMaxTooHigh: return "range_max_too_high";
    case ProblemKind::kBadRangeMax: return "bad_range_max";
    case ProblemKind::kNoValidReading: return "no_valid_reading";
    case ProblemKind::kMostlyNoReturns: return "mostly_no_returns";
    case ProblemKind::kOdometryJump: return "odometry_jump";
    case ProblemKind::kOdometryStall: return "odometry_stall";
    case ProblemKind::kHeadingWrap: return "heading_wrap";
    case ProblemKind::kOdometryVelocityMismatch: return "odometry_velocity_mismatch";
    case ProblemKind::kTfMissing: return "tf_missing";
    case ProblemKind::kTfLate: return "tf_late";
    case ProblemKind::kNoLaserOffset: return "no_laser_offset";
    case ProblemKind::kTfLoop: return "tf_loop";
    case ProblemKind::kSeveralScanTopics: return "several_scan_topics";
    case ProblemKind::kMalformedMessages: return "malformed_messages";
    case ProblemKind::kTruncatedRecording: return "truncated_recording";
  }
  return "unknown";
}

bool CheckReport::Has(ProblemKind kind) const {
  return std::any_of(problems.begin(), problems.end(), [&](const CheckProblem& p) { return p.kind == kind; });
}

CheckReport CheckLog(const LaserLog& log, const CheckOptions& options) {
  options.Validate();
  return CheckParts(log, StampsOf(log), options);
}

CheckReport CheckRecording(const std::string& path, const LogReadOptions& read, const CheckOptions& options) {
  options.Validate();
  LogReadOptions attempt = read;
  attempt.beams = BeamPolicy::kNode;
  attempt.Validate();
  if (DetectRecordingKind(path) == RecordingKind::kCarmenLog) return CheckLog(ReadLaserLog(path, attempt), options);
  return CheckRecordingContents(ReadRecordingContents(path, read.lenient), attempt, options);
}

CheckReport CheckRecordingContents(const RecordingContents& contents, const LogReadOptions& read,
                                   const CheckOptions& options) {
  options.Validate();
  const std::string& path = contents.path;
  LogReadOptions attempt = read;
  attempt.beams = BeamPolicy::kNode;
  attempt.Validate();
  std::vector<CheckProblem> early;
  if (attempt.recording.scan_topic.empty() && contents.scans.size() > 1) {
    std::string names, busiest;
    std::size_t most = 0;
    for (const auto& [name, scans] : contents.scans) {
      names += fmt::format("{}{} ({})", names.empty() ? "" : ", ", name, scans.size());
      if (scans.size() > most) most = scans.size(), busiest = name;
    }
    early.push_back({ProblemKind::kSeveralScanTopics,
                     fmt::format("{} LaserScan topics: {}; the rest of the check reads {} (choose with --scan-topic)",
                                 contents.scans.size(), names, busiest),
                     contents.scans.size(),
                     {},
                     {}});
    attempt.recording.scan_topic = busiest;
  }
  LaserLog log;
  try {
    log = RecordingToLog(contents, attempt);
  } catch (const TfLoopError& e) {
    // Nothing can be placed: the report says what the recording holds, and the loop.
    CheckReport report;
    report.path = path;
    for (const RecordedTopic& t : contents.container.topics) {
      report.facts.push_back(fmt::format("topic: {} ({}), {} messages", t.name, t.type, t.messages));
    }
    for (const std::string& e : contents.tf.Describe()) report.facts.push_back("tf: " + e);
    report.problems = early;
    report.problems.push_back({ProblemKind::kTfLoop, e.message() + "; nothing else can be checked", 1, {}, {}});
    return report;
  } catch (const InputError& e) {
    const bool no_offset = std::string(e.what()).find("no laser offset") != std::string::npos;
    if (!no_offset || attempt.recording.laser_offset) throw;
    early.push_back({ProblemKind::kNoLaserOffset,
                     std::string(e.what()) + " (the rest of the check assumes the laser at the base)",
                     1,
                     {},
                     {}});
    attempt.recording.laser_offset = Pose2{};
    log = RecordingToLog(contents, attempt);
  }
  HarmonizeBeams(BeamPolicy::kNode, &log);
  std::vector<double> stamps;
  for (const RecordedScan& s : contents.scans.at(log.recording->scan_topic)) {
    stamps.push_back(static_cast<double>(s.message.header.stamp_ns) / 1e9);
  }
  CheckReport report = CheckParts(log, stamps, options);
  CheckLateness(contents, log, options, &report);
  report.problems.insert(report.problems.begin(), early.begin(), early.end());
  report.path = path;
  return report;
}

std::string FormatCheckReport(const CheckReport& report) {
  std::string out = fmt::format("check {}\n", report.path);
  for (const std::string& fact : report.facts) out += "  " + fact + "\n";
  if (report.ok()) return out + "verdict: no problem found\n";
  std::string kinds;
  for (const CheckProblem& p : report.problems) {
    out += fmt::format("problem {}: {}\n", ProblemKindName(p.kind), p.what);
    if (!p.scans.empty()) {
      std::string where;
      for (std::size_t k = 0; k < p.scans.size(); ++k) {
        where += fmt::format("{}scan {} ({:.3f} s)", k ? ", " : "", p.scans[k], p.times_s[k]);
      }
      out += fmt::format("  at {}{}\n", where,
                         p.count > p.scans.size() ? fmt::format(" and {} more", p.count - p.scans.size()) : "");
    }
    kinds += (kinds.empty() ? "" : ", ") + std::string(ProblemKindName(p.kind));
  }
  return out + fmt::format("verdict: {} problem{}: {}\n", report.problems.size(),
                           report.problems.size() == 1 ? "" : "s", kinds);
}

}  // namespace slamtune::io
