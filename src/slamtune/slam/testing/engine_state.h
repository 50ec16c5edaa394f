// Test helpers for whole runs of the engine: parameters that keep a run short, and the check
// that two runs decided and computed exactly the same (used wherever a speed-up, a copy or a
// second laser must change nothing).
#pragma once

#include "slamtune/slam/log_runner.h"
#include "slamtune/slam/params/mapper_params.h"

namespace slamtune::slam::testing {

// Fewer, sparser nodes than the defaults keep a whole run around a second.
MapperParams FastMapperParams();

// Everything the engine decided and computed (poses, graph, buffers, counters, loop attempts,
// trajectory) is the same in `a` and `b`, as gtest expectations; the count of near-chain matches
// skipped by the response bound (fast_matching/response_bound.h) only when `same_skips`.
void ExpectSameEngineState(const LogRunner& a, const LogRunner& b, bool same_skips = true);

}  // namespace slamtune::slam::testing
