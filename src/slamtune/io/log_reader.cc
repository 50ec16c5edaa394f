#include "slamtune/io/log_reader.h"

#include <fmt/format.h>

#include "slamtune/common/error.h"
#include "slamtune/io/beam_geometry.h"
#include "slamtune/io/carmen/carmen_reader.h"
#include "slamtune/io/ros/recording_log.h"
#include "slamtune/io/ros/ros_recording.h"

namespace slamtune::io {

LaserLog ReadLaserLog(const std::string& path, const LogReadOptions& options) {
  options.Validate();
  LaserLog log = DetectRecordingKind(path) == RecordingKind::kCarmenLog ? ReadCarmenLog(path, options)
                                                                        : ReadRecordingLog(path, options);
  HarmonizeBeams(options.beams, &log);
  return log;
}

void RequireRanges(const LaserLog& log) {
  if (log.scans.empty() || CountRanges(log) > 0) return;
  throw InputError(log.path, 0,
                   fmt::format("not one of the {} readings of the {} scans is a range (each is inf, NaN, negative, "
                               "at or above range_max {} m or at or below range_min): nothing to map",
                               log.total_readings, log.scans.size(), log.scans.front().max_range));
}

}  // namespace slamtune::io
