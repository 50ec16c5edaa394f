// Parsers of single CARMEN records (one line split into fields, field 0 = record name), used
// by carmen_reader.cc, and the FLASER beam geometry rule, which writers of FLASER records
// (carmen_writer.h, the simulator) follow too. Layouts and conventions are documented in
// carmen_reader.h.
//
// A malformed record throws CarmenRecordError with a message naming the record and the problem
// (no file or line: the reader adds "FILE:LINE: " and decides whether to skip it).
#pragma once

#include <cstddef>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "slamtune/io/laser_log.h"

namespace slamtune::io::carmen {

class CarmenRecordError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

using Fields = std::vector<std::string_view>;

// FLASER: ranges, beam geometry by the FLASER rule, laser and robot poses, times. max_range
// is left at +inf (the reader sets the log's no-return value).
LaserScanRecord ParseFlaser(const Fields& f);

// ROBOTLASER1: ranges, geometry and max_range from the record, laser and robot poses, times.
LaserScanRecord ParseRobotLaser(const Fields& f);

// RAWLASER1..4: like ROBOTLASER1 without poses (the reader interpolates them from ODOM).
LaserScanRecord ParseRawLaser(const Fields& f);

OdomRecord ParseOdom(const Fields& f);

// PARAM name value host time, or the newer CARMEN form PARAM name value ipc_timestamp host
// logger_timestamp (recognised when the fields third from last and last are both numbers
// with a decimal point, as CARMEN writes its timestamps) -> (name, value); a value made of
// several fields is re-joined with single spaces.
std::pair<std::string, std::string> ParseParam(const Fields& f);

}  // namespace slamtune::io::carmen

namespace slamtune::io {

// The FLASER beam geometry rule (carmen_reader.h): first beam angle and increment (rad) for n
// readings.
void FlaserBeamGeometry(std::size_t num_readings, double* angle_min, double* angle_increment);

}  // namespace slamtune::io
