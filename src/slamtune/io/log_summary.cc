#include "slamtune/io/log_summary.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "slamtune/common/karto_math.h"
#include "slamtune/io/beam_geometry.h"
#include "slamtune/io/scan_losses.h"

namespace slamtune::io {
namespace {

bool SameGeometry(const LaserScanRecord& a, const LaserScanRecord& b) {
  return a.ranges.size() == b.ranges.size() && KartoEqual(a.angle_min, b.angle_min) &&
         KartoEqual(a.angle_increment, b.angle_increment);
}

}  // namespace

LogSummary SummarizeLog(const LaserLog& log) {
  LogSummary s;
  s.path = log.path;
  s.compressed = log.compressed;
  s.stopped_at_max_scans = log.stopped_at_max_scans;
  s.lines = log.lines_read;
  s.record_counts = log.record_counts;
  s.scans = log.scans.size();
  s.odometry_records = log.odometry.size();
  s.params = log.params.size();
  s.no_return_value_m = log.no_return_value;
  s.no_return_rule = log.no_return_rule;
  s.time_backward_steps = log.time_backward_steps;
  s.largest_backward_step_s = log.largest_backward_step_s;
  s.unknown_records = log.unknown_records;
  s.skipped_records = log.skipped_records;
  s.skipped_reasons = log.skipped_reasons;
  s.input = DescribeLogInput(log);
  if (log.scans.empty()) return s;

  const LaserScanRecord& first = log.scans.front();
  s.first_time_s = first.ipc_time;
  s.last_time_s = log.scans.back().ipc_time;
  s.duration_s = s.last_time_s - s.first_time_s;
  if (s.duration_s > 0 && s.scans > 1) s.scan_rate_hz = static_cast<double>(s.scans - 1) / s.duration_s;
  s.readings_per_scan = first.ranges.size();
  s.readings_per_scan_min = s.readings_per_scan_max = first.ranges.size();
  s.angle_min_deg = RadToDeg(first.angle_min);
  s.angular_resolution_deg = RadToDeg(first.angle_increment);
  s.angular_span_deg = RadToDeg(first.angle_increment * static_cast<double>(first.ranges.size() - 1));
  s.angle_max_deg = s.angle_min_deg + s.angular_span_deg;

  double min_reading = std::numeric_limits<double>::infinity();
  double max_reading = -std::numeric_limits<double>::infinity();
  double max_valid = -std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    const LaserScanRecord& scan = log.scans[i];
    s.readings_per_scan_min = std::min(s.readings_per_scan_min, scan.ranges.size());
    s.readings_per_scan_max = std::max(s.readings_per_scan_max, scan.ranges.size());
    if (!SameGeometry(scan, first)) s.geometry_varies = true;
    for (const double r : scan.ranges) {
      if (!std::isfinite(r)) continue;
      min_reading = std::min(min_reading, r);
      max_reading = std::max(max_reading, r);
      if (r >= 0.0 && r < scan.max_range) max_valid = std::max(max_valid, r);
    }
    s.readings += scan.ranges.size();
    s.no_returns += scan.no_returns;
    if (i > 0) {
      const Pose2& a = log.scans[i - 1].laser_pose;
      const Pose2& b = scan.laser_pose;
      s.odometry_path_m += std::sqrt(SquaredDistance(a, b));
      s.odometry_rotation_rad += std::fabs(NormalizeAngle(b.theta - a.theta));
    }
  }
  s.readings_per_scan_varies = s.readings_per_scan_min != s.readings_per_scan_max;
  s.min_reading_m = std::isfinite(min_reading) ? min_reading : 0.0;
  s.max_reading_m = std::isfinite(max_reading) ? max_reading : 0.0;
  s.max_valid_reading_m = std::isfinite(max_valid) ? max_valid : 0.0;
  s.no_return_fraction = s.readings > 0 ? static_cast<double>(s.no_returns) / static_cast<double>(s.readings) : 0.0;
  s.odometry_rotation_deg = RadToDeg(s.odometry_rotation_rad);
  return s;
}

std::vector<std::string> BeamLines(const LaserLog& log) {
  std::vector<std::string> out;
  const BeamReport& b = log.beams;
  if (b.varies()) {
    std::string seen;
    for (const BeamReport::Seen& g : b.geometries) {
      seen += fmt::format("{}{} ({} scans)", seen.empty() ? "" : "; ", g.geometry.ToString(), g.scans);
    }
    out.push_back(fmt::format("beams: {} geometries: {}", b.geometries.size(), seen));
  }
  const std::size_t n = log.scans.size();
  const std::size_t first = n == 0 ? 0 : log.scans.front().ranges.size();
  // "drops N of M scans: why", or "" when the node drops none.
  const auto dropped = [&](const NodeBeamCount& c) {
    if (c.dropped == 0) return std::string();
    if (c.expected != first) {
      return fmt::format(
          "drops {} of {} scans: the Karto laser it makes from the first scan expects {} readings "
          "(from angle_min, angle_max and angle_increment) and the first scan has {}",
          c.dropped, n, c.expected, first);
    }
    return fmt::format(
        "drops {} of {} scans: their beam count differs from the first scan's ({}); make the driver "
        "publish a fixed count",
        c.dropped, n, first);
  };
  const std::string karto = dropped(b.slam_karto);
  const std::string toolbox = dropped(b.slam_toolbox);
  if (!karto.empty() && karto == toolbox) {
    out.push_back("beams: the node (slam_karto and slam_toolbox alike) " + karto);
  } else {
    if (!karto.empty()) out.push_back("beams: slam_karto " + karto);
    if (!toolbox.empty()) out.push_back("beams: slam_toolbox " + toolbox);
  }
  if (b.policy == BeamPolicyName(BeamPolicy::kPerGeometry) && b.varies()) {
    out.push_back(
        fmt::format("beams: --beams per-geometry: one Karto laser for each of the {} geometries; no scan "
                    "dropped or changed (the node does not do this)",
                    b.geometries.size()));
  } else if (b.policy == BeamPolicyName(BeamPolicy::kNearestBeam) && b.scans_resampled > 0) {
    out.push_back(
        fmt::format("beams: --beams nearest-beam: {} scans resampled onto {} ({} readings outside their own "
                    "field of view set to no-return): an approximation, the node never sees these scans",
                    b.scans_resampled, b.geometries[0].geometry.ToString(), b.readings_outside));
  }
  return out;
}

namespace {

struct InputLine {
  std::string text;
  bool loss = false;  // says that data of the recording is not used
};

std::vector<InputLine> InputLines(const LaserLog& log) {
  std::vector<InputLine> out;
  const auto add = [&out](std::string text, bool loss = false) { out.push_back({std::move(text), loss}); };
  const ScanLosses losses = ReadingLosses(log);
  if (log.recording) {
    const RecordingInfo& r = *log.recording;
    const std::string ending =
        r.data_end.how.empty() ? (r.data_end.complete ? "complete" : "no end marker") : r.data_end.how;
    add(fmt::format("recording: {}, {} file{}; {}", r.format, r.files.size(), r.files.size() == 1 ? "" : "s", ending));
    add(fmt::format("scans: {} ({}), {} messages, {} used", r.scan_topic, r.scan_topic_rule, r.scan_messages,
                    log.scans.size()));
    add(fmt::format("odometry: {} ({})", r.odometry_source, r.odometry_rule));
    add(fmt::format("laser offset: x {:.4f} m, y {:.4f} m, yaw {:.3f} deg, {} ({}){}{}", r.laser_offset.x,
                    r.laser_offset.y, RadToDeg(r.laser_offset.theta),
                    r.laser_frame == r.base_frame ? r.base_frame : r.base_frame + " -> " + r.laser_frame,
                    r.laser_offset_source, r.upside_down ? "; upside down: readings reversed" : "",
                    r.laser_tilt_deg > 1.0 ? fmt::format("; tilted {:.1f} deg", r.laser_tilt_deg) : ""));
  }
  // Scans not used, but for their reading count: each node's count is in the beams lines.
  for (const ScanLoss& k : losses.kinds) {
    if (k.kind == ScanLossKind::kWrongReadingCount) continue;
    ScanLosses one;
    one.kinds.push_back(k);
    for (const std::string& line : one.LossLines()) add(line, true);
  }
  if (log.recording) {
    const RecordingInfo& r = *log.recording;
    if (r.messages_undecodable > 0) {
      add(fmt::format("not used: {} undecodable tf / odometry messages, --lenient", r.messages_undecodable), true);
    }
    for (const std::string& loop : r.tf_loops) {
      add(
          fmt::format("note: the tf tree has a loop, {}, away from the frames used (tf2 refuses every lookup through "
                      "it)",
                      loop));
    }
    if (r.scans_bad_range_max > 0) {
      add(fmt::format("note: LaserScan range_max is NaN, infinite, 0 or negative in {} of {} scans (first: {}): {}",
                      r.scans_bad_range_max, r.scan_messages, r.bad_range_max_example, kBadRangeMaxRule));
    }
    if (r.scans_other_frame > 0) {
      add(fmt::format("note: {} scans name another frame than {} (read as {})", r.scans_other_frame, r.laser_frame,
                      r.laser_frame));
    }
  }
  for (const std::string& line : BeamLines(log)) add(line, line.find(" drops ") != std::string::npos);
  if (log.skipped_records > log.skipped_scans) {
    add(fmt::format("not used: {} malformed records, --lenient (first: {})", log.skipped_records,
                    log.skipped_reasons.empty() ? "-" : log.skipped_reasons.front()),
        true);
  }
  return out;
}

}  // namespace

std::vector<std::string> DescribeLogInput(const LaserLog& log) {
  std::vector<std::string> out;
  for (const InputLine& line : InputLines(log)) out.push_back(line.text);
  return out;
}

std::vector<std::string> InputLossLines(const LaserLog& log) {
  std::vector<std::string> out;
  for (const InputLine& line : InputLines(log)) {
    if (line.loss) out.push_back(line.text);
  }
  return out;
}

std::vector<std::pair<std::string, std::string>> InputRows(const std::vector<std::string>& lines) {
  std::vector<std::pair<std::string, std::string>> rows;
  for (const std::string& line : lines) {
    const std::size_t colon = line.find(": ");
    if (colon == std::string::npos) {
      rows.emplace_back(line, "");
    } else {
      rows.emplace_back(line.substr(0, colon), line.substr(colon + 2));
    }
  }
  return rows;
}

std::string FormatLogSummary(const LogSummary& s) {
  std::string out;
  auto row = [&out](std::string_view key, const std::string& value) { out += fmt::format("{:<24} {}\n", key, value); };
  row("log", s.path + (s.compressed ? " (gzip)" : "") + (s.stopped_at_max_scans ? " (first scans only)" : ""));
  for (const auto& [name, value] : InputRows(s.input)) row(name, value);
  if (s.lines > 0) row("lines", std::to_string(s.lines));
  std::string counts;
  for (const auto& [name, count] : s.record_counts) {
    counts += fmt::format("{}{} {}", counts.empty() ? "" : ", ", name, count);
  }
  row("records", counts);
  row("laser scans", std::to_string(s.scans));
  row("odometry records", std::to_string(s.odometry_records));
  row("time span", fmt::format("{:.6f} .. {:.6f} s", s.first_time_s, s.last_time_s));
  row("duration",
      fmt::format("{:.3f} s ({:.2f} min), {:.2f} scans/s", s.duration_s, s.duration_s / 60.0, s.scan_rate_hz));
  row("readings per scan", s.readings_per_scan_varies
                               ? fmt::format("varies: {} .. {}", s.readings_per_scan_min, s.readings_per_scan_max)
                               : std::to_string(s.readings_per_scan));
  row("beam angles",
      fmt::format("{:.2f} .. {:.2f} deg (span {:.2f} deg, step {:.4f} deg){}", s.angle_min_deg, s.angle_max_deg,
                  s.angular_span_deg, s.angular_resolution_deg, s.geometry_varies ? ", varies between scans" : ""));
  row("readings", fmt::format("{} (min {:.3f} m, max {:.3f} m, max below no-return {:.3f} m)", s.readings,
                              s.min_reading_m, s.max_reading_m, s.max_valid_reading_m));
  row("no-return value", fmt::format("{} m (rule: {})", s.no_return_value_m, s.no_return_rule));
  row("no-returns", fmt::format("{} ({:.2f} % of the readings)", s.no_returns, 100.0 * s.no_return_fraction));
  row("odometry path", fmt::format("{:.3f} m", s.odometry_path_m));
  row("odometry rotation", fmt::format("{:.3f} rad ({:.1f} deg)", s.odometry_rotation_rad, s.odometry_rotation_deg));
  row("time backward steps", fmt::format("{} (largest {:.6f} s)", s.time_backward_steps, s.largest_backward_step_s));
  row("unknown records", std::to_string(s.unknown_records));
  row("skipped (malformed)", std::to_string(s.skipped_records));
  for (const std::string& reason : s.skipped_reasons) row("  skipped at line", reason);
  return out;
}

}  // namespace slamtune::io
