// `slamtune info` as library work: what a log holds (io/log_summary.h) — a CARMEN log or a ROS
// recording, read as every command reads it (tune/log_input.h) — and the summary as one JSON
// object.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "slamtune/io/log_summary.h"
#include "slamtune/tune/log_input.h"

namespace slamtune::tune {

struct LogInfoOptions {
  std::string log;        // CARMEN log (plain or gzip) or ROS recording
  LogInputOptions input;  // how it is read
};

// The log read with options.input and summarised. InputError for an unreadable log or a bad option.
io::LogSummary SummarizeLogFile(const LogInfoOptions& options);

// The summary as `info --json` prints it: every field under its own name, an unknown no-return
// value as null.
nlohmann::ordered_json ToJson(const io::LogSummary& summary);

}  // namespace slamtune::tune
