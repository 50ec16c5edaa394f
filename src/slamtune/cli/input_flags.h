// The flags of the options the commands share, each registered here once with one help text:
// how a log is read (tune::LogInputOptions), the tuning inputs (tune::TuningInputOptions), the
// node and its defaults (--preset) and how SLAM runs are carried out (tune::TuningRunOptions).
#pragma once

#include <CLI/CLI.hpp>
#include <string>
#include <vector>

#include "slamtune/tune/log_input.h"
#include "slamtune/tune/tuning_inputs.h"

namespace slamtune::cli {

// Whether a command offers --max-scans (one that checks a whole log does not).
enum class MaxScansFlag { kOffer, kOmit };

// --lenient, --no-return, --max-scans, --beams and the ROS recording choices.
void AddLogInputFlags(CLI::App& app, tune::LogInputOptions& options, MaxScansFlag max_scans = MaxScansFlag::kOffer);

// --out (the CARMEN log to write), --quiet and the log's flags: convert and fault.
void AddCarmenOutputFlags(CLI::App& app, std::string& out, bool& quiet, tune::LogInputOptions& input);

// --preset: the node and its defaults (slam/params/base_configuration.h).
CLI::Option* AddPresetFlag(CLI::App& app, std::string& preset);

// --relations, --world, --world-seed, --preset, --params, --set and the log's flags.
void AddTuningInputFlags(CLI::App& app, tune::TuningInputOptions& options);

// --jobs/-j and --quiet/-q; returns them.
std::vector<CLI::Option*> AddParallelismFlags(CLI::App& app, tune::TuningRunOptions& run);
// --no-share and --share-mb; returns them.
std::vector<CLI::Option*> AddSharingFlags(CLI::App& app, tune::TuningRunOptions& run);

}  // namespace slamtune::cli
