#include "slamtune/optim/evaluation/batch_evaluator.h"

#include <chrono>
#include <cmath>
#include <cstdint>
#include <exception>
#include <set>
#include <thread>

#include "slamtune/common/error.h"
#include "slamtune/optim/objective_set.h"
#include "slamtune/optim/search_space.h"

namespace slamtune::optim {

EvaluationRecord RunGuarded(const EvaluateFn& evaluate, const Assignment& assignment, const std::string& key) {
  const auto start = std::chrono::steady_clock::now();
  EvaluationRecord record;
  try {
    record = evaluate(assignment);
    record.key = key;
    record.params = assignment;
    for (Objective objective : AllObjectives()) {
      if (record.status == RunStatus::kOk && !std::isfinite(ValueOf(record, objective))) {
        record = EvaluationRecord::Failed(key, assignment, "non-finite objective value");
        break;
      }
    }
  } catch (const std::exception& e) {
    record = EvaluationRecord::Failed(key, assignment, e.what());
  }
  if (record.status != RunStatus::kOk) {
    record.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  return record;
}

BatchEvaluator::BatchEvaluator(EvaluateFn evaluate, EvaluationStore* store, int jobs)
    : evaluate_(std::move(evaluate)), store_(store), jobs_(jobs) {
  SLAMTUNE_CHECK(evaluate_ != nullptr);
  if (jobs_ < 1) throw InputError("--jobs must be >= 1, got " + std::to_string(jobs_));
}

BatchEvaluatorStats BatchEvaluator::stats() const {
  std::lock_guard guard(mutex_);
  return stats_;
}

BatchEvaluator::BatchLookup BatchEvaluator::Lookup(const std::vector<Assignment>& batch) {
  BatchLookup lookup;
  lookup.keys.resize(batch.size());
  std::set<std::string> seen;
  for (std::size_t i = 0; i < batch.size(); ++i) {
    const std::string& key = lookup.keys[i] = SearchSpace::Key(batch[i]);
    if (!seen.insert(key).second) continue;
    std::optional<EvaluationRecord> cached;
    {
      std::lock_guard guard(mutex_);
      auto it = memory_.find(key);
      if (it != memory_.end()) cached = it->second;
    }
    if (!cached && store_) cached = store_->Get(key);
    if (cached) {
      lookup.known[key] = *cached;
    } else {
      lookup.todo.push_back(i);
    }
  }
  return lookup;
}

std::vector<EvaluationRecord> BatchEvaluator::RunTodo(const std::vector<Assignment>& batch, const BatchLookup& lookup) {
  const std::vector<std::size_t>& todo = lookup.todo;
  const std::vector<std::string>& keys = lookup.keys;
  std::vector<EvaluationRecord> fresh(todo.size());
  // The store lists the records in the batch's order, not in the order the runs finish.
  const std::int64_t first_place = store_ ? store_->ReserveOrder(todo.size()) : 0;
  std::atomic<std::size_t> next{0};
  // Bookkeeping of one finished evaluation, local or remote.
  enum class RanOn { kThisProcess, kWorkerRank };
  auto finish = [&](std::size_t t, EvaluationRecord record, RanOn ran_on) {
    const std::size_t i = todo[t];
    fresh[t] = std::move(record);
    // Committed at once: an interruption loses nothing finished.
    if (store_) store_->Put(fresh[t], first_place + static_cast<std::int64_t>(t));
    BatchEvaluatorStats snapshot;
    {
      std::lock_guard guard(mutex_);
      memory_[keys[i]] = fresh[t];
      ++stats_.evaluated;
      if (ran_on == RanOn::kWorkerRank) ++stats_.remote;
      if (fresh[t].status != RunStatus::kOk) ++stats_.failed;
      stats_.busy_s += fresh[t].wall_s;
      snapshot = stats_;
    }
    // Outside the lock: the callback may ask for stats().
    if (progress_) {
      std::lock_guard guard(progress_mutex_);
      progress_(fresh[t], snapshot);
    }
  };
  auto worker = [&] {
    for (std::size_t t = next++; t < todo.size(); t = next++) {
      const std::size_t i = todo[t];
      finish(t, RunGuarded(evaluate_, batch[i], keys[i]), RanOn::kThisProcess);
    }
    idle_slots_->fetch_add(1);  // nothing left for this slot: the runs still going may use it
  };
  const bool use_remote = remote_ != nullptr && remote_->slots() > 0 && !todo.empty();
  // With remote slots the calling thread drives them, so local threads need not cover the batch.
  const int threads = std::min<int>(jobs_, static_cast<int>(todo.size()));
  idle_slots_->store(std::max(0, jobs_ - std::max(threads, 1)));
  if (threads <= 1 && !use_remote) {
    worker();
  } else {
    std::vector<std::thread> pool;
    for (int t = 0; t < threads; ++t) pool.emplace_back(worker);
    if (use_remote) {
      try {
        remote_->Drain(
            [&]() -> std::optional<RemoteEvaluators::Task> {
              const std::size_t t = next++;
              if (t >= todo.size()) return std::nullopt;
              return RemoteEvaluators::Task{t, batch[todo[t]]};
            },
            [&](std::size_t t, EvaluationRecord record) {
              SLAMTUNE_CHECK(t < todo.size());
              record.key = keys[todo[t]];
              record.params = batch[todo[t]];
              finish(t, std::move(record), RanOn::kWorkerRank);
            });
      } catch (...) {
        next = todo.size();  // local threads stop taking work; finished ones are stored
        for (auto& th : pool) th.join();
        throw;
      }
    }
    for (auto& th : pool) th.join();
  }
  idle_slots_->store(0);
  return fresh;
}

std::vector<EvaluationRecord> BatchEvaluator::Evaluate(const std::vector<Assignment>& batch) {
  {
    std::lock_guard guard(mutex_);
    stats_.requested += batch.size();
  }
  BatchLookup lookup = Lookup(batch);
  const std::vector<EvaluationRecord> fresh = RunTodo(batch, lookup);
  for (std::size_t t = 0; t < lookup.todo.size(); ++t) lookup.known[lookup.keys[lookup.todo[t]]] = fresh[t];
  std::vector<EvaluationRecord> out;
  out.reserve(batch.size());
  {
    std::lock_guard guard(mutex_);
    stats_.cache_hits += batch.size() - lookup.todo.size();
  }
  for (std::size_t i = 0; i < batch.size(); ++i) out.push_back(lookup.known.at(lookup.keys[i]));
  return out;
}

}  // namespace slamtune::optim
