#include "slamtune/tune/log_input.h"

#include <fmt/format.h>

#include <cstdio>

#include "slamtune/common/error.h"
#include "slamtune/io/beam_geometry.h"
#include "slamtune/io/log_reader.h"
#include "slamtune/io/log_summary.h"

namespace slamtune::tune {

io::LogReadOptions LogInputOptions::ToReadOptions() const {
  io::LogReadOptions o;
  o.lenient = lenient;
  o.no_return_value = no_return;
  o.max_scans = max_scans;
  o.beams = io::ParseBeamPolicy(beams);
  o.recording.scan_topic = scan_topic;
  o.recording.odom_topic = odom_topic;
  o.recording.odom_frame = odom_frame;
  o.recording.base_frame = base_frame;
  if (!laser_offset.empty()) o.recording.laser_offset = Pose2{laser_offset[0], laser_offset[1], laser_offset[2]};
  o.recording.max_odom_gap_s = max_odom_gap_s;
  o.Validate();
  return o;
}

nlohmann::json LogInputOptions::ToJson() const {
  return {{"lenient", lenient},           {"no_return", no_return},
          {"max_scans", max_scans},       {"beams", beams},
          {"scan_topic", scan_topic},     {"odom_topic", odom_topic},
          {"odom_frame", odom_frame},     {"base_frame", base_frame},
          {"laser_offset", laser_offset}, {"max_odom_gap_s", max_odom_gap_s}};
}

LogInputOptions LogInputOptions::FromJson(const nlohmann::json& j) {
  LogInputOptions o;
  o.lenient = j.at("lenient");
  o.no_return = j.at("no_return");
  o.max_scans = j.at("max_scans");
  o.beams = j.at("beams");  // older folders' "strict" and "resample" kept as written (same policies)
  o.scan_topic = j.at("scan_topic");
  o.odom_topic = j.at("odom_topic");
  o.odom_frame = j.at("odom_frame");
  o.base_frame = j.at("base_frame");
  o.laser_offset = j.at("laser_offset").get<std::vector<double>>();
  o.max_odom_gap_s = j.at("max_odom_gap_s");
  return o;
}

void LogInputOptions::RequireLogForSlice(const std::string& world) const {
  if (max_scans == 0) return;
  throw InputError(
      fmt::format("--max-scans {}: reads the first scans of a LOG; the built-in world '{}' is simulated whole (write "
                  "it to a log with `slamtune simulate --world {} --out DIR` and give that log)",
                  max_scans, world, world));
}

io::LaserLog ReadLog(const std::string& path, const LogInputOptions& options) {
  return io::ReadLaserLog(path, options.ToReadOptions());
}

void PrintLogInput(const io::LaserLog& log, bool quiet) {
  for (const std::string& line : quiet ? io::InputLossLines(log) : io::DescribeLogInput(log)) {
    std::fprintf(stderr, "%s\n", line.c_str());
  }
}

}  // namespace slamtune::tune
