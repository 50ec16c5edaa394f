#include "slamtune/io/carmen/carmen_reader.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <optional>

#include "slamtune/common/error.h"
#include "slamtune/io/carmen/carmen_records.h"
#include "slamtune/io/line_reader.h"

namespace slamtune::io {
namespace {

using carmen::CarmenRecordError;

constexpr std::size_t kMaxSkippedReasons = 10;  // reasons kept under --lenient
constexpr double kClusterMinFraction = 0.0005;  // rule 4: >= 0.05 % of the FLASER readings ...
constexpr double kClusterBand = 0.01;           // ... within 1 % below the largest reading

// Rule 2 of the no-return precedence (carmen_reader.h).
bool IsLaserMaxRangeParam(std::string_view name) {
  if (name.find("rear") != std::string_view::npos) return false;
  return name.ends_with("laser_max_range") || name == "robot_front_laser_max";
}

// Mounting-offset PARAM prefix of RAWLASER1..4 (carmen_reader.h).
std::string RawLaserParamPrefix(char digit) {
  switch (digit) {
    case '1': return "robot_frontlaser";
    case '2': return "robot_rearlaser";
    case '3': return "robot_laser3";
    default: return "robot_laser4";
  }
}

// The mounting-offset PARAMs read for RAWLASER scans (validated as numbers when read).
bool IsOffsetParam(std::string_view name) {
  for (const char digit : {'1', '2', '3', '4'}) {
    const std::string prefix = RawLaserParamPrefix(digit);
    if (name == prefix + "_offset" || name == prefix + "_side_offset" || name == prefix + "_angular_offset") {
      return true;
    }
  }
  return false;
}

bool IsRawLaser(std::string_view type) {
  return type.size() == 9 && type.starts_with("RAWLASER") && type[8] >= '1' && type[8] <= '4';
}

// State carried through one read.
struct ReadState {
  LaserLog log;
  std::vector<char> raw_digit;  // per scan: '1'..'4' for RAWLASER scans, 0 otherwise
  // Rule 3: largest record max_range and the record type that gave it.
  double record_max_range = 0.0;
  std::string record_max_kind;
  // Rule 2: the last laser max-range PARAM.
  std::string param_name;
  double param_value = 0.0;
  double latest_raw_time = -std::numeric_limits<double>::infinity();
};

void AddScan(LaserScanRecord scan, char raw_digit, ReadState* st) {
  LaserLog& log = st->log;
  if (!log.scans.empty() && scan.ipc_time < log.scans.back().ipc_time) {
    ++log.time_backward_steps;
    log.largest_backward_step_s = std::max(log.largest_backward_step_s, log.scans.back().ipc_time - scan.ipc_time);
  }
  if (scan.kind != RecordKind::kFlaser && scan.max_range > st->record_max_range) {
    st->record_max_range = scan.max_range;
    st->record_max_kind = raw_digit != 0 ? std::string("RAWLASER") + raw_digit : "ROBOTLASER1";
  }
  if (raw_digit != 0) st->latest_raw_time = std::max(st->latest_raw_time, scan.ipc_time);
  log.scans.push_back(std::move(scan));
  st->raw_digit.push_back(raw_digit);
}

void HandleParam(const carmen::Fields& f, ReadState* st) {
  auto [name, value] = carmen::ParseParam(f);
  if (IsLaserMaxRangeParam(name) || IsOffsetParam(name)) {
    const auto number = ParseDouble(value);
    if (!number || !std::isfinite(*number)) {
      throw CarmenRecordError("PARAM " + name + " value '" + value + "' is not a finite number");
    }
    if (IsLaserMaxRangeParam(name)) {
      if (*number <= 0) throw CarmenRecordError("PARAM " + name + " value '" + value + "' must be a positive range");
      st->param_name = name;
      st->param_value = *number;
    }
  }
  st->log.params[name] = value;
}

// Parses one non-comment record; unknown record types are counted and skipped.
void HandleRecord(const carmen::Fields& f, std::size_t line, ReadState* st) {
  const std::string_view type = f[0];
  if (type == "FLASER" || type == "ROBOTLASER1" || IsRawLaser(type)) {
    LaserScanRecord scan = type == "FLASER"        ? carmen::ParseFlaser(f)
                           : type == "ROBOTLASER1" ? carmen::ParseRobotLaser(f)
                                                   : carmen::ParseRawLaser(f);
    scan.line = line;
    AddScan(std::move(scan), IsRawLaser(type) ? type[8] : 0, st);
  } else if (type == "ODOM") {
    OdomRecord odom = carmen::ParseOdom(f);
    odom.line = line;
    st->log.odometry.push_back(odom);
  } else if (type == "PARAM") {
    HandleParam(f, st);
  } else {
    ++st->log.unknown_records;
  }
}

double ParamNumber(const LaserLog& log, const std::string& name) {
  const auto it = log.params.find(name);
  if (it == log.params.end()) return 0.0;
  return ParseDouble(it->second).value_or(0.0);  // validated when the PARAM was read
}

// Robot pose at time t, linear in time between the bracketing ODOM records (clamped outside).
Pose2 InterpolateOdometry(const std::vector<OdomRecord>& by_time, double t) {
  const auto after = std::lower_bound(by_time.begin(), by_time.end(), t,
                                      [](const OdomRecord& o, double time) { return o.ipc_time < time; });
  if (after == by_time.begin()) return by_time.front().pose;
  if (after == by_time.end()) return by_time.back().pose;
  const OdomRecord& a = *(after - 1);
  const OdomRecord& b = *after;
  if (b.ipc_time <= a.ipc_time) return b.pose;
  const double s = (t - a.ipc_time) / (b.ipc_time - a.ipc_time);
  return Pose2{a.pose.x + s * (b.pose.x - a.pose.x), a.pose.y + s * (b.pose.y - a.pose.y),
               NormalizeAngle(a.pose.theta + s * NormalizeAngle(b.pose.theta - a.pose.theta))};
}

// Poses RAWLASER scans from the ODOM records; scans outside the records' time span are left
// out and counted (LaserLog::scans_without_odometry) rather than clamped to the nearest record.
void PlaceRawLaserScans(ReadState* st) {
  LaserLog& log = st->log;
  if (st->latest_raw_time == -std::numeric_limits<double>::infinity()) return;
  if (log.odometry.empty()) {
    throw InputError(log.path, 0,
                     "RAWLASER scans carry no pose and the log has no ODOM record to interpolate one from");
  }
  std::vector<OdomRecord> by_time = log.odometry;
  std::stable_sort(by_time.begin(), by_time.end(),
                   [](const OdomRecord& a, const OdomRecord& b) { return a.ipc_time < b.ipc_time; });
  const double first_odom = by_time.front().ipc_time, last_odom = by_time.back().ipc_time;
  std::size_t kept = 0;
  for (std::size_t i = 0; i < log.scans.size(); ++i) {
    LaserScanRecord& scan = log.scans[i];
    if (st->raw_digit[i] != 0) {
      if (scan.ipc_time < first_odom || scan.ipc_time > last_odom) {
        if (log.scans_without_odometry++ == 0) {
          log.first_scan_without_odometry =
              fmt::format("line {} at {} s; ODOM {} .. {} s", scan.line, scan.ipc_time, first_odom, last_odom);
        }
        continue;
      }
      const std::string prefix = RawLaserParamPrefix(st->raw_digit[i]);
      const Pose2 offset{ParamNumber(log, prefix + "_offset"), ParamNumber(log, prefix + "_side_offset"),
                         ParamNumber(log, prefix + "_angular_offset")};
      scan.robot_pose = InterpolateOdometry(by_time, scan.ipc_time);
      scan.laser_offset = offset;
      scan.laser_pose = Compose(scan.robot_pose, offset);
    }
    if (kept != i) log.scans[kept] = std::move(scan);
    ++kept;
  }
  log.scans.resize(kept);
  if (log.scans.empty()) {
    throw InputError(log.path, 0,
                     fmt::format("none of the {} RAWLASER scans lies within the time span of the ODOM records, so "
                                 "none can be posed (first: {})",
                                 log.scans_without_odometry, log.first_scan_without_odometry));
  }
}

// Rule 4 of carmen_reader.h: the largest finite FLASER reading M if at least 0.05 % of the FLASER
// readings lie in [0.99 M, M]; nullopt otherwise.
std::optional<double> FlaserMaximumCluster(const LaserLog& log) {
  double largest = -std::numeric_limits<double>::infinity();
  std::size_t readings = 0;
  for (const LaserScanRecord& scan : log.scans) {
    if (scan.kind != RecordKind::kFlaser) continue;
    readings += scan.ranges.size();
    for (const double r : scan.ranges) {
      if (std::isfinite(r)) largest = std::max(largest, r);
    }
  }
  if (readings == 0 || !(largest > 0.0)) return std::nullopt;
  const double lower = (1.0 - kClusterBand) * largest;
  std::size_t in_cluster = 0;
  for (const LaserScanRecord& scan : log.scans) {
    if (scan.kind != RecordKind::kFlaser) continue;
    for (const double r : scan.ranges) in_cluster += (r >= lower && r <= largest) ? 1 : 0;
  }
  if (static_cast<double>(in_cluster) < kClusterMinFraction * static_cast<double>(readings)) return std::nullopt;
  return largest;
}

// The no-return precedence of carmen_reader.h, then per-scan max_range and no-return counts.
void ApplyNoReturnRule(const LogReadOptions& options, ReadState* st) {
  LaserLog& log = st->log;
  const bool override_all = options.no_return_value > 0;
  if (override_all) {
    log.no_return_value = options.no_return_value;
    log.no_return_rule = "--no-return";
  } else if (!st->param_name.empty()) {
    log.no_return_value = st->param_value;
    log.no_return_rule = "PARAM " + st->param_name;
  } else if (!st->record_max_kind.empty()) {
    log.no_return_value = st->record_max_range;
    log.no_return_rule = st->record_max_kind + " max_range";
  } else if (const auto cluster = FlaserMaximumCluster(log); cluster) {
    log.no_return_value = *cluster;
    log.no_return_rule = "maximum reading cluster";
  } else {
    log.no_return_value = std::numeric_limits<double>::infinity();
    log.no_return_rule = "none";
  }
  log.total_readings = 0;
  log.total_no_returns = 0;
  for (LaserScanRecord& scan : log.scans) {
    if (override_all || scan.kind == RecordKind::kFlaser) scan.max_range = log.no_return_value;
    std::size_t count = 0;
    for (const double r : scan.ranges) {
      // !(r < max) is true for r >= max and for NaN; +inf >= any max; negative readings too.
      if (!(r < scan.max_range) || r < 0.0 || std::isinf(r)) ++count;
    }
    scan.no_returns = count;
    log.total_readings += scan.ranges.size();
    log.total_no_returns += count;
  }
}

// The log of every line of `reader`, by the rules of carmen_reader.h.
LaserLog ReadLines(LineReader& reader, const LogReadOptions& options) {
  ReadState st;
  LaserLog& log = st.log;
  log.path = reader.name();
  log.compressed = reader.compressed();
  carmen::Fields fields;
  std::string_view line;
  bool any_content = false;
  bool draining = false;  // max_scans reached; only ODOM still needed to place RAWLASER scans
  while (reader.Next(&line)) {
    SplitFields(line, &fields);
    if (fields.empty()) continue;
    any_content = true;
    if (draining && fields[0] != "ODOM") continue;
    if (fields[0].front() == '#') {
      ++log.record_counts["#"];
      continue;
    }
    if (!draining) ++log.record_counts[std::string(fields[0])];
    try {
      HandleRecord(fields, reader.line_number(), &st);
    } catch (const CarmenRecordError& e) {
      std::string what = e.what();
      if (reader.unterminated()) what = "truncated last line (no newline at the end): " + what;
      if (!options.lenient) throw InputError(log.path, reader.line_number(), what);
      ++log.skipped_records;
      if (log.skipped_reasons.size() < kMaxSkippedReasons) {
        log.skipped_reasons.push_back(std::to_string(reader.line_number()) + ": " + what);
      }
      if (fields[0] == "FLASER" || fields[0] == "ROBOTLASER1" || fields[0].starts_with("RAWLASER")) {
        if (log.skipped_scans++ == 0) log.first_skipped_scan = fmt::format("line {}: {}", reader.line_number(), what);
      }
    }
    if (draining) {
      if (!log.odometry.empty() && log.odometry.back().ipc_time >= st.latest_raw_time) break;
      continue;
    }
    if (options.max_scans > 0 && log.scans.size() >= options.max_scans) {
      log.stopped_at_max_scans = true;
      const bool need_odometry = st.latest_raw_time > -std::numeric_limits<double>::infinity() &&
                                 (log.odometry.empty() || log.odometry.back().ipc_time < st.latest_raw_time);
      if (!need_odometry) break;
      draining = true;
    }
  }
  log.lines_read = reader.line_number();
  if (!any_content) throw InputError(log.path, 0, "empty file (no records)");
  if (log.scans.empty()) {
    throw InputError(
        log.path, 0,
        "no laser scans (FLASER, ROBOTLASER1 or RAWLASER1..4) in " + std::to_string(log.lines_read) + " lines" +
            (log.skipped_records > 0 ? " (" + std::to_string(log.skipped_records) + " skipped as malformed)"
                                     : std::string()));
  }
  PlaceRawLaserScans(&st);
  ApplyNoReturnRule(options, &st);
  return std::move(st.log);
}

}  // namespace

LaserLog ReadCarmenLog(const std::string& path, const LogReadOptions& options) {
  options.Validate();
  LineReader reader(path);
  return ReadLines(reader, options);
}

LaserLog ReadCarmenLog(std::istream& in, const std::string& name, const LogReadOptions& options) {
  options.Validate();
  if (!in.good()) throw InputError(name, 0, "cannot read the stream");
  LineReader reader(&in, name);
  return ReadLines(reader, options);
}

}  // namespace slamtune::io
