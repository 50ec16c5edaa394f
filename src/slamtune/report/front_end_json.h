// The front-end evidence of a run (slam/front_end_evidence.h) as JSON, one shape for every
// output that carries it: `run`'s run.json (`front_end`) and optimize's results.json
// (`base_front_end`, with the space choice added beside it).
#pragma once

#include <nlohmann/json.hpp>

#include "slamtune/slam/front_end_evidence.h"

namespace slamtune::report {

// {sequential_matches, median_response, at_edge, low_response, breaks, degenerate,
//  points_at_front_end, stretches: [...], degenerate_stretches: [...]}; times in s since the
// log's first scan, lengths in m.
nlohmann::json FrontEndEvidenceJson(const slam::FrontEndEvidence& evidence);

}  // namespace slamtune::report
