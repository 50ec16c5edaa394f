#include "slamtune/optim/evaluation_store.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <sqlite3.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/optim/objective_set.h"

namespace slamtune::optim {
namespace {

using slamtune::testing::ErrorMessageOf;

std::string FreshPath(const std::string& name) {
  return (slamtune::testing::UniqueTempDir("store_" + name) / "run.sqlite").string();
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

// Runs `sql` on the database at `path` and returns the first column of each row as text.
std::vector<std::string> Column(const std::string& path, const std::string& sql) {
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READWRITE, nullptr), SQLITE_OK);
  sqlite3_stmt* stmt = nullptr;
  EXPECT_EQ(sqlite3_prepare_v2(db, sql.c_str(), -1, &stmt, nullptr), SQLITE_OK) << sqlite3_errmsg(db);
  std::vector<std::string> out;
  while (sqlite3_step(stmt) == SQLITE_ROW) {
    const unsigned char* text = sqlite3_column_text(stmt, 0);
    out.emplace_back(text == nullptr ? "" : reinterpret_cast<const char*>(text));
  }
  sqlite3_finalize(stmt);
  sqlite3_close(db);
  return out;
}

TEST(EvaluationStore, StatusIsStoredAsOkOrFailedText) {
  const std::string path = FreshPath("status");
  {
    EvaluationStore store(path);
    store.Put(Sample(0));
    store.Put(EvaluationRecord::Failed("f", {}, "solver diverged"));
  }
  EXPECT_EQ(Column(path, "SELECT status FROM evaluations ORDER BY seq"), (std::vector<std::string>{"ok", "failed"}));
  std::vector<std::string> statuses;
  for (const std::string& record : Column(path, "SELECT record FROM evaluations ORDER BY seq")) {
    statuses.push_back(nlohmann::json::parse(record).at("status").get<std::string>());
  }
  EXPECT_EQ(statuses, (std::vector<std::string>{"ok", "failed"}));
  EvaluationStore store(path);
  EXPECT_EQ(store.Get("r=0")->status, RunStatus::kOk);
  EXPECT_EQ(store.Get("f")->status, RunStatus::kFailed);
}

TEST(EvaluationStore, AnUnknownStoredStatusIsAnInputError) {
  const std::string path = FreshPath("unknown_status");
  EvaluationStore(path).Put(EvaluationRecord::Failed("f", {}, "solver diverged"));
  Column(path, "UPDATE evaluations SET record = replace(record, '\"status\":\"failed\"', '\"status\":\"passed\"')");
  EXPECT_THAT([&] { EvaluationStore(path).Get("f"); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("unknown evaluation status 'passed'")));
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

TEST(EvaluationStore, RecordsListByTheirPlaceNotByWhenTheyWerePut) {
  const std::string path = FreshPath("places");
  {
    EvaluationStore store(path);
    store.Put(Sample(0));
    const std::int64_t first = store.ReserveOrder(3);
    store.Put(Sample(9));  // after the reserved places
    store.Put(Sample(3), first + 2);
    store.Put(Sample(1), first);
    store.Put(Sample(2), first + 1);
  }
  std::vector<std::string> keys;
  for (const EvaluationRecord& r : EvaluationStore(path).All()) keys.push_back(r.key);
  EXPECT_EQ(keys, (std::vector<std::string>{"r=0", "r=1", "r=2", "r=3", "r=9"}));
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

TEST(EvaluationStore, StartRunStoresSettingsAndCommandLineTogether) {
  const std::string path = FreshPath("start");
  { EvaluationStore(path).StartRun({{"seed", 3}}, {{"population", 8}}); }
  EvaluationStore store(path);
  EXPECT_EQ(store.Settings()->at("seed"), 3);
  EXPECT_EQ(store.Meta("invocation")->at("population"), 8);
}

// A run database of several pages, closed (its WAL folded into the file).
std::string FilledDatabase(const std::string& name) {
  const std::string path = FreshPath(name);
  EvaluationStore store(path);
  store.StartRun({{"seed", 1}}, {});
  for (int i = 0; i < 200; ++i) store.Put(Sample(i));
  return path;
}

void Overwrite(const std::string& path, std::streamoff offset, const std::string& bytes) {
  std::fstream file(path, std::ios::in | std::ios::out | std::ios::binary);
  file.seekp(offset);
  file.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

TEST(CheckRunDatabase, IntactDatabasePasses) {
  const std::string path = FilledDatabase("intact");
  EXPECT_NO_THROW(CheckRunDatabase(path));
  EXPECT_EQ(EvaluationStore(path).Count(), 200u);
}

TEST(CheckRunDatabase, CorruptPageIsRefusedNamingTheFile) {
  const std::string path = FilledDatabase("page");
  ASSERT_GT(std::filesystem::file_size(path), 5u * 4096);
  Overwrite(path, 4 * 4096, std::string(4096, '\x5a'));
  const std::string message = ErrorMessageOf([&] { CheckRunDatabase(path); });
  EXPECT_EQ(message.rfind(path + ": the run database is damaged (", 0), 0u) << message;
  EXPECT_EQ(message.find('\n'), std::string::npos) << message;
}

TEST(CheckRunDatabase, OverwrittenHeaderIsRefused) {
  const std::string path = FilledDatabase("header");
  Overwrite(path, 0, "not a database header, really");
  EXPECT_EQ(ErrorMessageOf([&] { CheckRunDatabase(path); }),
            path +
                ": the run database is damaged (file is not a database); it cannot be resumed: start again with "
                "a new --out (the report files beside it stay readable)");
}

}  // namespace
}  // namespace slamtune::optim
