// Evaluates batches of parameter sets: each distinct set at most once (the run database is
// the cache, so a set evaluated in an earlier generation or before an interruption is never
// run again), the missing ones in parallel on `jobs` threads, each result committed to the
// database the moment it finishes. A failing evaluation (exception or non-finite objective)
// is recorded with its reason and scored worst; the batch goes on.
#pragma once

#include <atomic>
#include <functional>
#include <map>
#include <mutex>
#include <string>
#include <vector>

#include "slamtune/optim/evaluation_record.h"
#include "slamtune/optim/evaluation_store.h"

namespace slamtune::optim {

using Assignment = std::map<std::string, double>;
// Runs one evaluation (a SLAM run and its map metrics). Must be thread-safe and
// deterministic: the same assignment always gives the same record. May throw.
using EvaluateFn = std::function<EvaluationRecord(const Assignment&)>;

struct BatchEvaluatorStats {
  std::size_t requested = 0;   // assignments asked for
  std::size_t evaluated = 0;   // SLAM runs done by this process
  std::size_t cache_hits = 0;  // served from the database or from a duplicate in the batch
  std::size_t failed = 0;      // evaluations recorded as failed
  double busy_s = 0.0;         // summed wall time of this process's evaluations
};

class BatchEvaluator {
 public:
  // `store` may be null (no persistence, in-memory cache only). jobs >= 1.
  BatchEvaluator(EvaluateFn evaluate, EvaluationStore* store, int jobs);

  // Results in the order of `batch`.
  std::vector<EvaluationRecord> Evaluate(const std::vector<Assignment>& batch);

  // Called after each finished evaluation (from worker threads, serialised).
  void SetProgressCallback(std::function<void(const EvaluationRecord&, const BatchEvaluatorStats&)> cb) {
    progress_ = std::move(cb);
  }
  BatchEvaluatorStats stats() const;
  int jobs() const { return jobs_; }

 private:
  EvaluationRecord RunOne(const Assignment& assignment, const std::string& key);

  EvaluateFn evaluate_;
  EvaluationStore* store_;
  int jobs_;
  mutable std::mutex mutex_;
  std::mutex progress_mutex_;  // serialises progress callbacks
  std::map<std::string, EvaluationRecord> memory_;  // cache when there is no store
  BatchEvaluatorStats stats_;
  std::function<void(const EvaluationRecord&, const BatchEvaluatorStats&)> progress_;
};

}  // namespace slamtune::optim
