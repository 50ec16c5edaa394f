#include "slamtune/optim/evaluation_store.h"
#include "slamtune/optim/objective_set.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

#include "slamtune/common/error.h"

namespace slamtune::optim {
namespace {

std::string FreshPath(const std::string& name) {
  const auto path = std::filesystem::temp_directory_path() / ("slamtune_store_" + name + ".sqlite");
  std::filesystem::remove(path);
  std::filesystem::remove(path.string() + "-wal");
  std::filesystem::remove(path.string() + "-shm");
  return path.string();
}

EvaluationRecord Sample(int i) {
  EvaluationRecord r;
  r.key = "r=" + std::to_string(i);
  r.params = {{"loop_search_maximum_distance", 2.0 + i}, {"loop_match_minimum_chain_size", 10}};
  r.occupied_ratio = 0.03 + i * 1e-3;
  r.corner_pixels = 100 + i;
  r.enclosed_areas = 7;
  r.nodes = 1000;
  r.loop_closures = 3;
  r.loop_scans = {10, 20, 30};
  r.has_gt = i % 2 == 0;
  r.trans_mean_m = 0.05;
  r.relations_used = 100;
  return r;
}

TEST(EvaluationStore, RecordsSurviveReopening) {
  const std::string path = FreshPath("reopen");
  {
    EvaluationStore store(path);
    store.SetSettings({{"seed", 7}});
    for (int i = 0; i < 5; ++i) store.Put(Sample(i));
    store.PutGeneration(0, {{"x", {1, 2}}});
  }
  EvaluationStore store(path);
  EXPECT_EQ(store.Count(), 5u);
  EXPECT_EQ(store.Settings()->at("seed"), 7);
  const auto r = store.Get("r=2");
  ASSERT_TRUE(r.has_value());
  EXPECT_DOUBLE_EQ(r->occupied_ratio, Sample(2).occupied_ratio);
  EXPECT_EQ(r->loop_scans, (std::vector<int>{10, 20, 30}));
  EXPECT_TRUE(r->has_gt);
  EXPECT_FALSE(store.Get("r=1")->has_gt);
  EXPECT_FALSE(store.Get("missing").has_value());
  EXPECT_EQ(store.LastGeneration(), 0);
  EXPECT_EQ(store.All().front().key, "r=0");
}

TEST(EvaluationStore, FailedRecordsScoreWorst) {
  const auto f = EvaluationRecord::Failed("k", {}, "solver diverged");
  EXPECT_EQ(ObjectiveSet(ObjectiveSetKind::kPaper).Score(f), (std::vector<double>{1.0, 1e9, 1e9}));
  EXPECT_EQ(ObjectiveSet(ObjectiveSetKind::kConsistency).Score(f), (std::vector<double>{2.0, 1e9, 1e9}));
}

TEST(EvaluationStore, ConcurrentPutsAreAllKept) {
  EvaluationStore store(FreshPath("threads"));
  std::vector<std::thread> threads;
  for (int t = 0; t < 4; ++t) {
    threads.emplace_back([&store, t] {
      for (int i = 0; i < 10; ++i) store.Put(Sample(t * 10 + i));
    });
  }
  for (auto& th : threads) th.join();
  EXPECT_EQ(store.Count(), 40u);
}

TEST(EvaluationStore, RejectsNonDatabaseFile) {
  const std::string path = FreshPath("garbage");
  std::ofstream(path) << "this is not sqlite, just text that is long enough to have a header page";
  try {
    EvaluationStore store(path);
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("not a slamtune run database"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace slamtune::optim
