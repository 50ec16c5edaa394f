#include "slamtune/optim/objective_set.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"

namespace slamtune::optim {
namespace {

using ::testing::HasSubstr;

EvaluationRecord Record(double hits, double in_free, double in_unknown) {
  EvaluationRecord r;
  r.occupied_ratio = 0.05;
  r.corner_pixels = 1200;
  r.enclosed_areas = 7;
  r.hits = hits;
  r.hits_in_free_cells = in_free;
  r.hits_in_unknown_cells = in_unknown;
  r.occupied_cells = 21000;
  return r;
}

TEST(ObjectiveSet, TheDefaultIsConsistencyAndThePaperKeepsEta) {
  EXPECT_EQ(ObjectiveSet().kind(), ObjectiveSetKind::kConsistency);
  EXPECT_EQ(ObjectiveSet().objectives(), (std::vector<Objective>{Objective("unbacked_hits"), Objective("corner_pixels"),
                                                                 Objective("enclosed_areas")}));
  EXPECT_EQ(
      ObjectiveSet(ObjectiveSetKind::kPaper).objectives(),
      (std::vector<Objective>{Objective("occupied_ratio"), Objective("corner_pixels"), Objective("enclosed_areas")}));
  EXPECT_EQ(
      ObjectiveSet(ObjectiveSetKind::kOccupied).objectives(),
      (std::vector<Objective>{Objective("unbacked_hits"), Objective("corner_pixels"), Objective("occupied_cells")}));
}

TEST(ObjectiveSet, TheOccupiedSetCountsWallCellsSoATwiceMappedCorridorScoresWorse) {
  EvaluationRecord once = Record(1000, 30, 20);
  EvaluationRecord twice = once;  // the same end points, a second copy of the corridor's walls
  twice.occupied_cells = 2 * once.occupied_cells;
  const ObjectiveSet occupied(ObjectiveSetKind::kOccupied);
  EXPECT_EQ(occupied.Score(once), (std::vector<double>{0.05, 1200, 21000}));
  EXPECT_LT(occupied.Score(once)[2], occupied.Score(twice)[2]);
  // The default set cannot tell the two apart.
  EXPECT_EQ(ObjectiveSet().Score(once), ObjectiveSet().Score(twice));
}

TEST(ObjectiveSet, TheDrawnSetReadsTheWallDrawnAlongThePath) {
  EvaluationRecord r = Record(1000, 30, 20);
  r.drawn_wall_cells = 30500;
  const ObjectiveSet drawn(ObjectiveSetKind::kDrawn);
  EXPECT_EQ(drawn.Score(r), (std::vector<double>{0.05, 1200, 30500}));
  EXPECT_TRUE(drawn.Uses(Objective("drawn_wall_cells")));
  EXPECT_FALSE(ObjectiveSet(ObjectiveSetKind::kOccupied).Uses(Objective("drawn_wall_cells")));
}

TEST(ObjectiveSet, TheAutomaticChoiceCountsCellsOnlyWhenEveryRunDrawsTheSameScans) {
  EXPECT_EQ(DefaultObjectiveSetKind(false), ObjectiveSetKind::kOccupied);
  EXPECT_EQ(DefaultObjectiveSetKind(true), ObjectiveSetKind::kDrawn);
}

TEST(ObjectiveSet, UnbackedHitsAreTheShareOfEndPointsInFreeOrUnknownCells) {
  EXPECT_DOUBLE_EQ(ValueOf(Record(1000, 30, 20), Objective("unbacked_hits")), 0.05);
  EXPECT_DOUBLE_EQ(ValueOf(Record(1000, 0, 0), Objective("unbacked_hits")), 0.0);
  // No end point on the map: nothing backs it.
  EXPECT_DOUBLE_EQ(ValueOf(Record(0, 0, 0), Objective("unbacked_hits")), 1.0);
  EXPECT_EQ(ObjectiveSet().Score(Record(1000, 30, 20)), (std::vector<double>{0.05, 1200, 7}));
  EXPECT_EQ(ObjectiveSet(ObjectiveSetKind::kPaper).Score(Record(1000, 30, 20)), (std::vector<double>{0.05, 1200, 7}));
}

TEST(ObjectiveSet, FailedRunsScoreWorseThanAnyMapAndAreRecognised) {
  const auto failed = EvaluationRecord::Failed("k", {}, "solver diverged");
  for (const ObjectiveSet& set :
       {ObjectiveSet(ObjectiveSetKind::kConsistency), ObjectiveSet(ObjectiveSetKind::kOccupied),
        ObjectiveSet(ObjectiveSetKind::kDrawn), ObjectiveSet(ObjectiveSetKind::kPaper)}) {
    SCOPED_TRACE(set.name());
    const auto score = set.Score(failed);
    EXPECT_TRUE(set.IsFailureScore(score));
    const auto fine = set.Score(Record(1000, 1000, 0));  // even a map that backs no end point
    EXPECT_FALSE(set.IsFailureScore(fine));
    for (std::size_t k = 0; k < score.size(); ++k) EXPECT_GT(score[k], fine[k]);
    EXPECT_TRUE(set.IsFailureScore({0.1, 2.0}));  // wrong length
    EXPECT_TRUE(set.IsFailureScore({0.1, std::nan(""), 3.0}));
  }
}

TEST(ObjectiveSet, ParsesNamesAndRefusesUnknownOnes) {
  EXPECT_EQ(ObjectiveSet::Parse("paper").kind(), ObjectiveSetKind::kPaper);
  EXPECT_EQ(ObjectiveSet::Parse("consistency").kind(), ObjectiveSetKind::kConsistency);
  EXPECT_EQ(ObjectiveSet::Parse("occupied").kind(), ObjectiveSetKind::kOccupied);
  EXPECT_EQ(ObjectiveSet::Parse("drawn").kind(), ObjectiveSetKind::kDrawn);
  try {
    ObjectiveSet::Parse("eta");
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("unknown objective set 'eta' (known: drawn, occupied, consistency, paper)"));
  }
}

TEST(ObjectiveSet, DescribesItselfInWords) {
  EXPECT_EQ(ObjectiveSet().Describe(), "unbacked hits (u_h), corner pixels (n_c) and enclosed areas (n_e)");
  EXPECT_STREQ(InfoOf(Objective("occupied_ratio")).key, "occupied_ratio");
  EXPECT_EQ(ObjectiveSet(ObjectiveSetKind::kOccupied).Describe(),
            "unbacked hits (u_h), corner pixels (n_c) and occupied cells (n_o)");
  EXPECT_EQ(ObjectiveSet(ObjectiveSetKind::kDrawn).Describe(),
            "unbacked hits (u_h), corner pixels (n_c) and wall the log's scans draw along the path (n_w)");
  EXPECT_EQ(AllObjectives().size(), 6u);
}

}  // namespace
}  // namespace slamtune::optim
