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
  // Not `r.key = "k"`: GCC 12 at -O3 warns (-Wrestrict) on that inlined assignment, a false positive.
  r.key.push_back('k');
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
    EXPECT_EQ(figure.field == nullptr, figure.derived()) << figure.key;
    EXPECT_EQ(figure.derive != nullptr, figure.derived()) << figure.key;
    EXPECT_EQ(&FigureNamed(figure.key), &figure);
  }
}

TEST(RecordFigures, AnObjectiveHasNamesAndAFailureScoreAndAnyOtherFigureNone) {
  std::set<std::string> short_names;
  for (const RecordFigure& figure : RecordFigures()) {
    if (!figure.is_objective()) {
      EXPECT_EQ(figure.title, nullptr) << figure.key;
      EXPECT_EQ(figure.failure_score, 0.0) << figure.key;
      continue;
    }
    EXPECT_TRUE(short_names.insert(figure.short_name).second) << figure.short_name;
    ASSERT_NE(figure.title, nullptr) << figure.key;
    // The title names the short name, as the report's legends expect: "corner pixels (n_c)".
    EXPECT_THAT(figure.title, HasSubstr(std::string("(") + figure.short_name + ")"));
    EXPECT_GT(figure.failure_score, 0.0) << figure.key;
  }
  EXPECT_THAT(short_names, ::testing::UnorderedElementsAre("eta", "n_c", "n_e", "n_o", "u_h", "n_w"));
}

TEST(RecordFigures, EveryObjectiveReadsItsFigure) {
  std::vector<std::string> keys;
  for (Objective objective : AllObjectives()) keys.push_back(InfoOf(objective).key);
  EXPECT_THAT(keys, ElementsAre("occupied_ratio", "corner_pixels", "enclosed_areas", "occupied_cells", "unbacked_hits",
                                "drawn_wall_cells"));
  const EvaluationRecord r = RecordWithDistinctFigures();
  EXPECT_EQ(ValueOf(r, Objective("corner_pixels")), r.corner_pixels);
  EXPECT_EQ(ValueOf(r, Objective("drawn_wall_cells")), r.drawn_wall_cells);
  EXPECT_EQ(Objective("corner_pixels"), AllObjectives()[1]);
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

TEST(RecordFigures, JsonKeepsTheMeasuredFiguresAndReadsBackEveryFigure) {
  const EvaluationRecord r = RecordWithDistinctFigures();
  const nlohmann::json j = r;
  // Every measured figure in "figures", derived figures not at all.
  EXPECT_EQ(j.at("figures").size(), RecordFigures().size() - 1);
  EXPECT_EQ(j.at("figures").at("corner_pixels"), r.corner_pixels);
  EXPECT_EQ(j.at("figures").at("drawn_wall_cells"), r.drawn_wall_cells);
  EXPECT_FALSE(j.at("figures").contains("unbacked_hits"));
  EXPECT_FALSE(j.contains("objectives"));
  EXPECT_FALSE(j.contains("second"));
  const EvaluationRecord back = j.get<EvaluationRecord>();
  for (const RecordFigure& figure : RecordFigures()) {
    EXPECT_EQ(FigureValue(figure, back), FigureValue(figure, r)) << figure.key;
  }
}

// A record as run folders stored it in the earlier layout: the seed paper's three figures in
// "objectives", the other measured ones in "second".
nlohmann::json InEarlierLayout(const EvaluationRecord& r) {
  nlohmann::json j = r;
  nlohmann::json figures = j.at("figures");
  j.erase("figures");
  for (const char* key : {"occupied_ratio", "corner_pixels", "enclosed_areas"}) {
    j["objectives"][key] = figures.at(key);
    figures.erase(key);
  }
  j["second"] = figures;
  return j;
}

TEST(RecordFigures, ARecordInTheEarlierLayoutReadsBackEveryFigure) {
  const EvaluationRecord r = RecordWithDistinctFigures();
  const EvaluationRecord back = InEarlierLayout(r).get<EvaluationRecord>();
  for (const RecordFigure& figure : RecordFigures()) {
    EXPECT_EQ(FigureValue(figure, back), FigureValue(figure, r)) << figure.key;
  }
}

TEST(RecordFigures, ARecordStoredBeforeTheLaterFiguresReadsThemAsZero) {
  nlohmann::json j = InEarlierLayout(RecordWithDistinctFigures());
  for (const char* key :
       {"occupied_cells", "hits", "hits_in_free_cells", "hits_in_unknown_cells", "drawn_wall_cells"}) {
    j.at("second").erase(key);
  }
  const EvaluationRecord back = j.get<EvaluationRecord>();
  EXPECT_EQ(back.occupied_cells, 0.0);
  EXPECT_EQ(back.drawn_wall_cells, 0.0);
  EXPECT_EQ(back.corners, RecordWithDistinctFigures().corners);
  EXPECT_EQ(back.corner_pixels, RecordWithDistinctFigures().corner_pixels);
  // A figure every stored record has is required, in either layout.
  j.at("second").erase("corners");
  EXPECT_THROW(static_cast<void>(j.get<EvaluationRecord>()), nlohmann::json::exception);
  nlohmann::json current = RecordWithDistinctFigures();
  current.at("figures").erase("corner_pixels");
  EXPECT_THROW(static_cast<void>(current.get<EvaluationRecord>()), nlohmann::json::exception);
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
