#include "slamtune/optim/batch_evaluator.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <stdexcept>

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

TEST(BatchEvaluator, FailuresAreRecordedAndScoredWorst) {
  BatchEvaluator eval(Fake, nullptr, 1);
  const auto out = eval.Evaluate({{{"r", -1}}, {{"r", 6}}, {{"r", 1}}});
  EXPECT_EQ(out[0].status, "failed");
  EXPECT_EQ(out[0].reason, "negative radius");
  EXPECT_EQ(out[1].status, "failed");
  EXPECT_EQ(out[1].reason, "non-finite objective value");
  EXPECT_EQ(out[0].Objectives()[1], 1e9);
  EXPECT_EQ(out[2].status, "ok");
  EXPECT_EQ(eval.stats().failed, 2u);
}

TEST(BatchEvaluator, DatabaseServesEarlierResultsAcrossProcesses) {
  const auto path = (std::filesystem::temp_directory_path() / "slamtune_batch_eval.sqlite").string();
  std::filesystem::remove(path);
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
  for (std::size_t i = 0; i < batch.size(); ++i) EXPECT_EQ(a[i].Objectives(), b[i].Objectives());
}

}  // namespace
}  // namespace slamtune::optim
