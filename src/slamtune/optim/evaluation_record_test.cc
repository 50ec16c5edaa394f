#include "slamtune/optim/evaluation_record.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <set>
#include <string>

#include "slamtune/common/error.h"
#include "slamtune/optim/objective_set.h"

namespace slamtune::optim {
namespace {

using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// A record whose every stored figure holds a different value: 1, 2, 3, ... in table order.
EvaluationRecord RecordWithDistinctFigures() {
  EvaluationRecord r;
  r.key = "k";
  double value = 1.0;
  for (const RecordFigure& figure : RecordFigures()) {
    if (figure.field != nullptr) r.*figure.field = value++;
  }
  return r;
}

TEST(RunStatus, NamesAreOkAndFailedAndParseBack) {
  EXPECT_STREQ(NameOf(RunStatus::kOk), "ok");
  EXPECT_STREQ(NameOf(RunStatus::kFailed), "failed");
  EXPECT_EQ(ParseRunStatus("ok"), RunStatus::kOk);
  EXPECT_EQ(ParseRunStatus("failed"), RunStatus::kFailed);
}

TEST(RunStatus, OtherTextIsAnInputError) {
  EXPECT_THAT([] { ParseRunStatus("passed"); },
              ThrowsMessage<InputError>(HasSubstr("unknown evaluation status 'passed' (known: ok, failed)")));
  EXPECT_THROW(ParseRunStatus("OK"), InputError);
  EXPECT_THROW(ParseRunStatus(""), InputError);
}

TEST(EvaluationRecord, JsonHoldsTheStatusAsText) {
  EvaluationRecord ok;
  ok.key = "k";
  const nlohmann::json written = ok;
  EXPECT_EQ(written.at("status"), "ok");
  EXPECT_EQ(written.get<EvaluationRecord>().status, RunStatus::kOk);
  const EvaluationRecord failed = EvaluationRecord::Failed("k", {{"x", 1.0}}, "solver diverged");
  const nlohmann::json failed_json = failed;
  EXPECT_EQ(failed_json.at("status"), "failed");
  const EvaluationRecord back = failed_json.get<EvaluationRecord>();
  EXPECT_EQ(back.status, RunStatus::kFailed);
  EXPECT_EQ(back.reason, "solver diverged");
}

TEST(EvaluationRecord, AnUnknownStatusInJsonIsAnInputError) {
  nlohmann::json j = EvaluationRecord{};
  j["status"] = "done";
  EXPECT_THAT([&] { static_cast<void>(j.get<EvaluationRecord>()); },
              ThrowsMessage<InputError>(HasSubstr("unknown evaluation status 'done'")));
}

TEST(RecordFigures, KeysAreUniqueAndEachFigureIsStoredOrDerived) {
  std::set<std::string> keys;
  for (const RecordFigure& figure : RecordFigures()) {
    EXPECT_TRUE(keys.insert(figure.key).second) << figure.key;
    const bool derived = figure.storage == FigureStorage::kDerived;
    EXPECT_EQ(figure.field == nullptr, derived) << figure.key;
    EXPECT_EQ(figure.derive != nullptr, derived) << figure.key;
    EXPECT_EQ(&FigureNamed(figure.key), &figure);
  }
}

TEST(RecordFigures, EveryObjectiveReadsAFigure) {
  for (Objective objective : AllObjectives()) {
    EXPECT_STREQ(FigureNamed(InfoOf(objective).key).key, InfoOf(objective).key);
  }
  const EvaluationRecord r = RecordWithDistinctFigures();
  EXPECT_EQ(ValueOf(r, Objective::kCornerPixels), r.corner_pixels);
  EXPECT_EQ(ValueOf(r, Objective::kDrawnWallCells), r.drawn_wall_cells);
}

TEST(RecordFigures, TheUnbackedShareIsDerivedFromTheHits) {
  EvaluationRecord r;
  r.hits = 200;
  r.hits_in_free_cells = 30;
  r.hits_in_unknown_cells = 10;
  EXPECT_DOUBLE_EQ(FigureValue(FigureNamed("unbacked_hits"), r), 0.2);
  r.hits = 0;  // no end point on the map: nothing backs it
  EXPECT_EQ(FigureValue(FigureNamed("unbacked_hits"), r), 1.0);
}

TEST(RecordFigures, JsonKeepsTheRunDatabaseLayoutAndReadsBackEveryFigure) {
  const EvaluationRecord r = RecordWithDistinctFigures();
  const nlohmann::json j = r;
  // The layout stored run folders hold: the seed paper's three figures in "objectives", the
  // rest measured in "second", derived figures not at all.
  EXPECT_EQ(j.at("objectives").size(), 3u);
  EXPECT_EQ(j.at("objectives").at("corner_pixels"), r.corner_pixels);
  EXPECT_EQ(j.at("second").at("drawn_wall_cells"), r.drawn_wall_cells);
  EXPECT_FALSE(j.at("objectives").contains("unbacked_hits"));
  EXPECT_FALSE(j.at("second").contains("unbacked_hits"));
  const EvaluationRecord back = j.get<EvaluationRecord>();
  for (const RecordFigure& figure : RecordFigures()) {
    EXPECT_EQ(FigureValue(figure, back), FigureValue(figure, r)) << figure.key;
  }
}

TEST(RecordFigures, ARecordStoredBeforeTheLaterFiguresReadsThemAsZero) {
  nlohmann::json j = RecordWithDistinctFigures();
  for (const char* key :
       {"occupied_cells", "hits", "hits_in_free_cells", "hits_in_unknown_cells", "drawn_wall_cells"}) {
    j.at("second").erase(key);
  }
  const EvaluationRecord back = j.get<EvaluationRecord>();
  EXPECT_EQ(back.occupied_cells, 0.0);
  EXPECT_EQ(back.drawn_wall_cells, 0.0);
  EXPECT_EQ(back.corners, RecordWithDistinctFigures().corners);
  // A figure every stored record has is required.
  j.at("second").erase("corners");
  EXPECT_THROW(static_cast<void>(j.get<EvaluationRecord>()), nlohmann::json::exception);
}

TEST(RecordFigures, AreInTheColumnOrderOfTheTables) {
  std::vector<std::string> keys;
  for (const RecordFigure& figure : RecordFigures()) keys.push_back(figure.key);
  EXPECT_THAT(keys, ElementsAre("occupied_ratio", "corner_pixels", "enclosed_areas", "occupied_ratio_known", "corners",
                                "contours", "occupied_cells", "hits", "hits_in_free_cells", "hits_in_unknown_cells",
                                "unbacked_hits", "drawn_wall_cells"));
}

}  // namespace
}  // namespace slamtune::optim
