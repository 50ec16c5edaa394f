#include "slamtune/tune/log_info.h"

#include "slamtune/report/json_number.h"

namespace slamtune::tune {

io::LogSummary SummarizeLogFile(const LogInfoOptions& options) {
  return io::SummarizeLog(ReadLog(options.log, options.input));
}

nlohmann::ordered_json ToJson(const io::LogSummary& s) {
  return {
      {"path", s.path},
      {"compressed", s.compressed},
      {"stopped_at_max_scans", s.stopped_at_max_scans},
      {"lines", s.lines},
      {"record_counts", s.record_counts},
      {"scans", s.scans},
      {"odometry_records", s.odometry_records},
      {"params", s.params},
      {"first_time_s", s.first_time_s},
      {"last_time_s", s.last_time_s},
      {"duration_s", s.duration_s},
      {"scan_rate_hz", s.scan_rate_hz},
      {"readings_per_scan", s.readings_per_scan},
      {"readings_per_scan_min", s.readings_per_scan_min},
      {"readings_per_scan_max", s.readings_per_scan_max},
      {"readings_per_scan_varies", s.readings_per_scan_varies},
      {"angle_min_deg", s.angle_min_deg},
      {"angle_max_deg", s.angle_max_deg},
      {"angular_span_deg", s.angular_span_deg},
      {"angular_resolution_deg", s.angular_resolution_deg},
      {"geometry_varies", s.geometry_varies},
      {"min_reading_m", s.min_reading_m},
      {"max_reading_m", s.max_reading_m},
      {"max_valid_reading_m", s.max_valid_reading_m},
      {"no_return_value", report::FiniteOrNull<nlohmann::ordered_json>(s.no_return_value_m)},
      {"no_return_rule", s.no_return_rule},
      {"readings", s.readings},
      {"no_returns", s.no_returns},
      {"no_return_fraction", s.no_return_fraction},
      {"odometry_path_m", s.odometry_path_m},
      {"odometry_rotation_rad", s.odometry_rotation_rad},
      {"odometry_rotation_deg", s.odometry_rotation_deg},
      {"time_backward_steps", s.time_backward_steps},
      {"largest_backward_step_s", s.largest_backward_step_s},
      {"unknown_records", s.unknown_records},
      {"skipped_records", s.skipped_records},
      {"skipped_reasons", s.skipped_reasons},
      {"input", s.input},
  };
}

}  // namespace slamtune::tune
