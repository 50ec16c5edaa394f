#include "slamtune/optim/evaluation/batch_evaluator.h"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <stdexcept>
#include <thread>
#include <vector>

#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/optim/objective_set.h"

namespace slamtune::optim {
namespace {

EvaluationRecord Fake(const Assignment& a) {
  const double r = a.at("r");
  if (r < 0) throw std::runtime_error("negative radius");
  EvaluationRecord rec;
  rec.occupied_ratio = r * 0.01;
  rec.corner_pixels = r * r;
  rec.enclosed_areas = r > 5 ? std::nan("") : 1.0;
  return rec;
}

TEST(BatchEvaluator, RunsEachDistinctSetOnceAndKeepsOrder) {
  std::atomic<int> calls{0};
  BatchEvaluator eval(
      [&](const Assignment& a) {
        ++calls;
        return Fake(a);
      },
      nullptr, 2);
  const auto out = eval.Evaluate({{{"r", 1}}, {{"r", 2}}, {{"r", 1}}, {{"r", 3}}});
  ASSERT_EQ(out.size(), 4u);
  EXPECT_EQ(calls.load(), 3);
  EXPECT_DOUBLE_EQ(out[1].corner_pixels, 4.0);
  EXPECT_EQ(out[0].key, out[2].key);
  eval.Evaluate({{{"r", 2}}});
  EXPECT_EQ(calls.load(), 3);
  EXPECT_EQ(eval.stats().cache_hits, 2u);
  EXPECT_EQ(eval.stats().evaluated, 3u);
}

// A slot with nothing to run is offered to the evaluations still going: all but one slot of a
// single-set batch, and none once the batch is over.
TEST(BatchEvaluator, IdleSlotsAreOfferedToTheRunsStillGoing) {
  std::shared_ptr<const std::atomic<int>> idle;
  std::atomic<int> seen{-1};
  BatchEvaluator eval(
      [&](const Assignment& a) {
        seen = idle->load();
        return Fake(a);
      },
      nullptr, 3);
  idle = eval.idle_slots();
  eval.Evaluate({{{"r", 1}}});
  EXPECT_EQ(seen.load(), 2);
  EXPECT_EQ(idle->load(), 0);
  BatchEvaluator serial(
      [&](const Assignment& a) {
        seen = idle->load();
        return Fake(a);
      },
      nullptr, 1);
  idle = serial.idle_slots();
  serial.Evaluate({{{"r", 1}}});
  EXPECT_EQ(seen.load(), 0);
}

TEST(BatchEvaluator, FailuresAreRecordedAndScoredWorst) {
  BatchEvaluator eval(Fake, nullptr, 1);
  const auto out = eval.Evaluate({{{"r", -1}}, {{"r", 6}}, {{"r", 1}}});
  EXPECT_EQ(out[0].status, RunStatus::kFailed);
  EXPECT_EQ(out[0].reason, "negative radius");
  EXPECT_EQ(out[1].status, RunStatus::kFailed);
  EXPECT_EQ(out[1].reason, "non-finite objective value");
  EXPECT_EQ(ObjectiveSet(ObjectiveSetKind::kPaper).Score(out[0])[1], 1e9);
  EXPECT_EQ(out[2].status, RunStatus::kOk);
  EXPECT_EQ(eval.stats().failed, 2u);
}

TEST(BatchEvaluator, DatabaseServesEarlierResultsAcrossProcesses) {
  const auto path = (slamtune::testing::UniqueTempDir("batch_eval") / "run.sqlite").string();
  {
    EvaluationStore store(path);
    BatchEvaluator eval(Fake, &store, 2);
    eval.Evaluate({{{"r", 1}}, {{"r", 2}}});
  }
  EvaluationStore store(path);
  int calls = 0;
  BatchEvaluator eval(
      [&](const Assignment& a) {
        ++calls;
        return Fake(a);
      },
      &store, 1);
  const auto out = eval.Evaluate({{{"r", 2}}, {{"r", 3}}});
  EXPECT_EQ(calls, 1);
  EXPECT_DOUBLE_EQ(out[0].corner_pixels, 4.0);
  EXPECT_EQ(store.Count(), 3u);
}

// With two runs at a time the later set finishes first; the store still lists the batch's order.
TEST(BatchEvaluator, TheStoreKeepsTheBatchOrderWhicheverRunFinishesFirst) {
  const auto path = (slamtune::testing::UniqueTempDir("batch_order") / "run.sqlite").string();
  EvaluationStore store(path);
  BatchEvaluator eval(
      [](const Assignment& a) {
        if (a.at("r") == 1) std::this_thread::sleep_for(std::chrono::milliseconds(200));
        return Fake(a);
      },
      &store, 2);
  eval.Evaluate({{{"r", 1}}, {{"r", 2}}});
  eval.Evaluate({{{"r", 3}}});
  std::vector<double> order;
  for (const EvaluationRecord& r : store.All()) order.push_back(r.params.at("r"));
  EXPECT_EQ(order, (std::vector<double>{1, 2, 3}));
}

TEST(BatchEvaluator, ProgressCallbackMayReadStats) {
  BatchEvaluator eval(Fake, nullptr, 2);
  std::size_t seen = 0;
  eval.SetProgressCallback([&](const EvaluationRecord&, const BatchEvaluatorStats&) { seen = eval.stats().evaluated; });
  eval.Evaluate({{{"r", 1}}, {{"r", 2}}, {{"r", 3}}});
  EXPECT_GE(seen, 1u);
}

TEST(BatchEvaluator, ParallelEqualsSerial) {
  std::vector<Assignment> batch;
  for (int i = 0; i < 20; ++i) batch.push_back({{"r", 0.1 * i}});
  BatchEvaluator serial(Fake, nullptr, 1), parallel(Fake, nullptr, 4);
  const auto a = serial.Evaluate(batch), b = parallel.Evaluate(batch);
  for (std::size_t i = 0; i < batch.size(); ++i) EXPECT_EQ(ObjectiveSet().Score(a[i]), ObjectiveSet().Score(b[i]));
}

// Remote slots served in this process, through the record's JSON as the MPI workers send it.
class LoopbackRemote final : public RemoteEvaluators {
 public:
  explicit LoopbackRemote(int slots) : slots_(slots) {}
  int slots() const override { return slots_; }
  void Drain(const std::function<std::optional<Task>()>& next,
             const std::function<void(std::size_t, EvaluationRecord)>& done) override {
    std::vector<Task> in_flight;
    for (;;) {
      while (static_cast<int>(in_flight.size()) < slots_) {
        auto task = next();
        if (!task) break;
        in_flight.push_back(*task);
      }
      if (in_flight.empty()) return;
      const Task task = in_flight.back();  // finish out of order, as ranks do
      in_flight.pop_back();
      const nlohmann::json wire = RunGuarded(Fake, task.second, "remote");
      done(task.first, wire.get<EvaluationRecord>());
      ++served;
    }
  }
  std::atomic<int> served{0};

 private:
  int slots_;
};

TEST(BatchEvaluator, RemoteSlotsGiveTheLocalResults) {
  std::vector<Assignment> batch;
  for (int i = 0; i < 30; ++i) batch.push_back({{"r", 0.37 * (i % 17) - 0.5}});  // duplicates and failures
  BatchEvaluator local(Fake, nullptr, 1);
  LoopbackRemote remote(3);
  // The local thread holds its first set until the remote slots have served one, so both kinds
  // of slot take part however the threads are scheduled (else the local thread may take all).
  std::atomic<bool> first{true};
  BatchEvaluator mixed(
      [&remote, &first](const Assignment& a) {
        if (first.exchange(false)) {
          const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
          while (remote.served.load() == 0 && std::chrono::steady_clock::now() < deadline) {
            std::this_thread::sleep_for(std::chrono::milliseconds(1));
          }
        }
        return Fake(a);
      },
      nullptr, 1);
  mixed.SetRemote(&remote);
  const auto a = local.Evaluate(batch), b = mixed.Evaluate(batch);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < batch.size(); ++i) {
    EXPECT_EQ(a[i].key, b[i].key);
    EXPECT_EQ(a[i].params, b[i].params);
    EXPECT_EQ(a[i].status, b[i].status);
    EXPECT_EQ(a[i].reason, b[i].reason);
    EXPECT_EQ(ObjectiveSet().Score(a[i]), ObjectiveSet().Score(b[i]));  // bit-exact through JSON
  }
  EXPECT_GT(remote.served.load(), 0);
  EXPECT_EQ(mixed.stats().remote, static_cast<std::size_t>(remote.served.load()));
  EXPECT_EQ(mixed.stats().evaluated, local.stats().evaluated);
  EXPECT_EQ(mixed.stats().failed, local.stats().failed);
}

TEST(BatchEvaluator, RemoteOnlyWhenItHasSlots) {
  BatchEvaluator eval(Fake, nullptr, 1);
  LoopbackRemote none(0);
  eval.SetRemote(&none);
  eval.Evaluate({{{"r", 1}}, {{"r", 2}}});
  EXPECT_EQ(none.served.load(), 0);
  EXPECT_EQ(eval.stats().evaluated, 2u);
}

}  // namespace
}  // namespace slamtune::optim
