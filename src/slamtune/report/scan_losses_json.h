// The scans not used (io/scan_losses.h) as JSON, one shape for every output that carries them:
// run.json, results.json and `check --json`, under `scans_not_used`.
#pragma once

#include <nlohmann/json.hpp>

#include "slamtune/io/scan_losses.h"

namespace slamtune::report {

// {NAME: {count, data_loss, what, [first], [bytes], [by]}} for each kind of `losses`: count null
// when the scans cannot be counted (cut_off), bytes for cut_off, `by` the counts by verdict
// (filtered_by_node) or by node (wrong_reading_count).
nlohmann::json ScanLossesJson(const io::ScanLosses& losses);

}  // namespace slamtune::report
