#include "slamtune/io/laser_log.h"

#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/io/line_reader.h"

namespace slamtune::io {

const char* RecordKindName(RecordKind kind) {
  switch (kind) {
    case RecordKind::kFlaser: return "FLASER";
    case RecordKind::kRobotLaser1: return "ROBOTLASER1";
    case RecordKind::kRawLaser: return "RAWLASER";
    case RecordKind::kOdom: return "ODOM";
    case RecordKind::kParam: return "PARAM";
    case RecordKind::kComment: return "#";
    case RecordKind::kUnknown: return "unknown";
  }
  return "unknown";
}

void LogReadOptions::Validate() const {
  if (!(no_return_value >= 0.0) || !std::isfinite(no_return_value)) {
    throw InputError("no_return_value = " + FormatExact(no_return_value) +
                     ": must be 0 (detect from the log) or a positive finite range in metres");
  }
}

}  // namespace slamtune::io
