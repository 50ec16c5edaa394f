#include "slamtune/io/log_reader.h"

#include "slamtune/io/beam_geometry.h"
#include "slamtune/io/carmen_reader.h"
#include "slamtune/io/recording_container.h"
#include "slamtune/io/recording_log.h"

namespace slamtune::io {

LaserLog ReadLaserLog(const std::string& path, const LogReadOptions& options) {
  options.Validate();
  LaserLog log = DetectRecordingKind(path) == RecordingKind::kCarmenLog ? ReadCarmenLog(path, options)
                                                                        : ReadRecordingLog(path, options);
  HarmonizeBeams(options.beams, &log);
  return log;
}

}  // namespace slamtune::io
