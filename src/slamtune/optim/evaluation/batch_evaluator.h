// Evaluates batches of parameter sets: each distinct set at most once (the run database is
// the cache, so a set evaluated in an earlier generation or before an interruption is never
// run again), the missing ones in parallel on `jobs` threads, each result committed to the
// database the moment it finishes. A failing evaluation (exception or non-finite objective)
// is recorded with its reason and scored worst; the batch goes on.
//
// Other processes can take part (mpi_evaluation.h): a RemoteEvaluators takes sets from the
// same queue as the local threads, on the calling thread, and hands back their records.
// Evaluations are deterministic, so who ran a set never changes a result.
#pragma once

#include <atomic>
#include <functional>
#include <map>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "slamtune/optim/evaluation_record.h"
#include "slamtune/optim/evaluation_store.h"

namespace slamtune::optim {

using Assignment = std::map<std::string, double>;
// Runs one evaluation (a SLAM run and its map metrics). Must be thread-safe and
// deterministic: the same assignment always gives the same record. May throw.
using EvaluateFn = std::function<EvaluationRecord(const Assignment&)>;

// Runs `evaluate` on one assignment and turns an exception or a non-finite objective into a
// failed record with its reason (wall time kept); never throws for a failing evaluation.
EvaluationRecord RunGuarded(const EvaluateFn& evaluate, const Assignment& assignment, const std::string& key);

// Evaluation slots outside this process (e.g. MPI worker ranks). Drain() runs on the thread
// that called BatchEvaluator::Evaluate, beside the local worker threads.
class RemoteEvaluators {
 public:
  using Task = std::pair<std::size_t, Assignment>;  // (task id, parameter set)
  virtual ~RemoteEvaluators() = default;
  // Number of sets evaluated at once remotely; 0 means none (Drain is not called).
  virtual int slots() const = 0;
  // Takes tasks from `next` (nullopt: none left) while a slot is free, and returns once every
  // task taken has come back through `done(task id, record)`. Throws on a broken transport.
  virtual void Drain(const std::function<std::optional<Task>()>& next,
                     const std::function<void(std::size_t, EvaluationRecord)>& done) = 0;
};

struct BatchEvaluatorStats {
  std::size_t requested = 0;   // assignments asked for
  std::size_t evaluated = 0;   // SLAM runs done by this process
  std::size_t cache_hits = 0;  // served from the database or from a duplicate in the batch
  std::size_t failed = 0;      // evaluations recorded as failed
  std::size_t remote = 0;      // of `evaluated`, how many ran in other processes
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
  // Other processes that evaluate beside the local threads (may be null: local only). Not
  // owned; must outlive the evaluator's Evaluate calls.
  void SetRemote(RemoteEvaluators* remote) { remote_ = remote; }
  // How many of the `jobs` local slots have no evaluation to run right now (at a batch's tail, or
  // in a batch smaller than jobs): an evaluation may use them for its own threads
  // (SlamEvaluationContext::idle_slots). Results never depend on it.
  std::shared_ptr<const std::atomic<int>> idle_slots() const { return idle_slots_; }

 private:
  // A batch split into what is known (memory or run database) and what must run.
  struct BatchLookup {
    std::vector<std::string> keys;                  // by batch index
    std::vector<std::size_t> todo;                  // indices of the first occurrence of each unknown key
    std::map<std::string, EvaluationRecord> known;  // by key
  };
  BatchLookup Lookup(const std::vector<Assignment>& batch);
  // Runs lookup.todo on the local threads and the remote slots; returns their records, by todo index.
  std::vector<EvaluationRecord> RunTodo(const std::vector<Assignment>& batch, const BatchLookup& lookup);

  EvaluateFn evaluate_;
  EvaluationStore* store_;
  int jobs_;
  RemoteEvaluators* remote_ = nullptr;
  mutable std::mutex mutex_;
  std::mutex progress_mutex_;                       // serialises progress callbacks
  std::map<std::string, EvaluationRecord> memory_;  // cache when there is no store
  BatchEvaluatorStats stats_;
  std::function<void(const EvaluationRecord&, const BatchEvaluatorStats&)> progress_;
  std::shared_ptr<std::atomic<int>> idle_slots_ = std::make_shared<std::atomic<int>>(0);
};

}  // namespace slamtune::optim
