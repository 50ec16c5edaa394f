// `slamtune check` as library work: what to know about a log or bag before tuning on it
// (io/check/log_check.h) — its topics and choices, and each problem with its scans and times — and the
// report as one JSON object.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "slamtune/io/check/log_check.h"
#include "slamtune/tune/log_input.h"

namespace slamtune::tune {

struct RecordingCheckOptions {
  std::string log;         // ROS recording or CARMEN log
  LogInputOptions input;   // how it is read (max_scans unused: the whole log is checked)
  io::CheckOptions check;  // the limits of each problem
};

// The recording read whole and checked. InputError for an unreadable file or a bad option.
io::CheckReport CheckRecordingFile(const RecordingCheckOptions& options);

// The report as `check --json` prints it: path, verdict (ok), facts, problems by kind, and the
// scans not used.
nlohmann::ordered_json ToJson(const io::CheckReport& report);

}  // namespace slamtune::tune
