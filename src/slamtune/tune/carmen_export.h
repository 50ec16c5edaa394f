// `slamtune convert` and `slamtune fault` as library work: what slamtune reads from a log or bag,
// written as a CARMEN log (io/carmen/carmen_writer.h) — as read (convert), or with planted
// odometry failures (fault, sim/log_faults.h) so that a tuner's repair of a broken front end can
// be measured on real scans against the recording's own relations.
//
// convert writes ROBOTLASER1 lines with the laser and the robot pose, ODOM lines, the laser offset
// and max range as PARAMs, so that other tools — a Karto build, Cartographer's or GMapping's
// CARMEN readers — read exactly the scans slamtune reads: the same topic, poses at the scan
// stamps, resampled beams, reversed readings of an upside-down laser. fault keeps FLASER scans
// FLASER and writes the others as convert does; its faults take the form and meaning of
// `simulate --fault` (sim/odometry_fault.h), located by the log's odometric travel, and the scans'
// readings and timestamps are kept. CARMEN holds finite numbers only: a no-return written as +inf
// or NaN in the recording is written as the scan's max range (the CARMEN convention), and counted.
// The log is written whole or not at all.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "slamtune/io/carmen/carmen_writer.h"
#include "slamtune/sim/log_faults.h"
#include "slamtune/tune/log_input.h"

namespace slamtune::tune {

struct ConvertOptions {
  std::string log;        // ROS recording or CARMEN log
  std::string out;        // CARMEN log to write
  LogInputOptions input;  // how the log is read
  bool quiet = false;     // on stderr only the data of the recording that is not used
};

// What was written.
struct CarmenExport {
  io::CarmenWriteSummary written;
  std::size_t non_finite_readings = 0;  // written as the max range
};

// "N scans, M ODOM records[, K non-finite readings written as the max range]; wrote OUT".
std::string DescribeExport(const CarmenExport& exported, const std::string& out);

// Reads options.log, says what was read on stderr (PrintLogInput) and writes it to options.out.
// InputError when out is a folder, before the log is read.
CarmenExport ConvertToCarmen(const ConvertOptions& options);

struct FaultOptions {
  std::string log;                  // CARMEN log or ROS recording
  std::string out;                  // CARMEN log to write
  std::vector<std::string> faults;  // KIND,START_M,LENGTH_M[,MAGNITUDE] (sim::ParseOdometryFault), in order
  LogInputOptions input;            // how the log is read
  bool quiet = false;               // on stderr only the data of the recording that is not used
};

struct FaultOutcome {
  sim::LogFaultSummary planted;  // the log's odometric travel and each fault as planted
  CarmenExport exported;
};

// Parses the faults and checks out (not a folder, in a folder that exists) before the log is read,
// then reads it, says what was read on stderr, plants the faults and writes the log. InputError
// without a fault, for a malformed fault, an unwritable out or a fault beyond the log's travel.
FaultOutcome PlantFaultsAndWrite(const FaultOptions& options);

}  // namespace slamtune::tune
