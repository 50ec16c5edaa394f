#include "slamtune/optim/candidate_selection.h"

#include <gtest/gtest.h>

#include "slamtune/optim/testing/objective_sets.h"

namespace slamtune::optim {
namespace {

using testing::kPaper;
using testing::PaperRecord;

VerdictSummary PaperVerdict(const EvaluationRecord& a, const EvaluationRecord& b) {
  VerdictOptions options;
  options.objectives = kPaper;
  return Verdict(a, b, options);
}

TEST(CandidateSelection, MajorityWinsThenObjectivesBreakTies) {
  const std::vector<EvaluationRecord> pop{PaperRecord("a", 0.03, 100, 5), PaperRecord("b", 0.02, 90, 4),
                                          PaperRecord("a", 0.03, 100, 5), PaperRecord("c", 0.05, 200, 9)};
  const auto rec = RecommendByMajority(pop, kPaper);
  EXPECT_EQ(pop[rec.index].key, "a");
  EXPECT_EQ(rec.share, 2);
  const std::vector<EvaluationRecord> tie{PaperRecord("a", 0.03, 100, 5), PaperRecord("b", 0.02, 90, 4)};
  EXPECT_EQ(tie[RecommendByMajority(tie, kPaper).index].key, "b");
}

TEST(CandidateSelection, FailedSetsAreNeverRecommendedWhenAnOkOneExists) {
  auto f = EvaluationRecord::Failed("x", {}, "boom");
  const std::vector<EvaluationRecord> pop{f, f, f, PaperRecord("a", 0.03, 100, 5)};
  EXPECT_EQ(pop[RecommendByMajority(pop, kPaper).index].key, "a");
}

TEST(CandidateSelection, AFailedRunsScoreDoesNotDecideBetweenRealMaps) {
  // Among the maps, b is better on n_c and n_e by far and worse on eta by a little. Normalised
  // over the maps alone b wins; a failed run's eta 1, n_c 1e9, n_e 1e9 in the ranges would
  // leave eta to decide alone, for a.
  auto failed = EvaluationRecord::Failed("x", {}, "broke");
  const std::vector<EvaluationRecord> pop{failed, PaperRecord("a", 0.030, 300, 30), PaperRecord("b", 0.031, 100, 5)};
  EXPECT_EQ(pop[RecommendByMajority(pop, kPaper).index].key, "b");
}

TEST(CandidateSelection, FrontKneeAndWorst) {
  const std::vector<EvaluationRecord> all{PaperRecord("lo-eta", 0.01, 300, 9), PaperRecord("mid", 0.02, 120, 4),
                                          PaperRecord("lo-nc", 0.05, 100, 8), PaperRecord("bad", 0.06, 400, 12),
                                          EvaluationRecord::Failed("f", {}, "x")};
  const auto front = NonDominated(all, kPaper);
  EXPECT_EQ(front, (std::vector<std::size_t>{0, 1, 2}));
  EXPECT_EQ(all[Knee(all, kPaper)].key, "mid");
  EXPECT_EQ(all[Worst(all, kPaper)].key, "bad");
}

TEST(CandidateSelection, VerdictCallsSmallDifferencesEquivalent) {
  const auto v = PaperVerdict(PaperRecord("r", 0.0300, 1000, 10), PaperRecord("d", 0.0301, 1005, 10)).text;
  EXPECT_EQ(v.rfind("Equivalent", 0), 0u) << v;
  EXPECT_NE(PaperVerdict(PaperRecord("r", 0.02, 800, 8), PaperRecord("d", 0.03, 1000, 10)).text.find("cleaner map"),
            std::string::npos);
  EXPECT_NE(PaperVerdict(PaperRecord("r", 0.04, 1200, 10), PaperRecord("d", 0.03, 1000, 10))
                .text.find("defaults score better"),
            std::string::npos);
  EXPECT_NE(PaperVerdict(PaperRecord("r", 0.02, 1200, 10), PaperRecord("d", 0.03, 1000, 10)).text.find("Mixed"),
            std::string::npos);
  EXPECT_EQ(PaperVerdict(PaperRecord("r", 0.02, 800, 8), PaperRecord("d", 0.03, 1000, 10)).kind, VerdictKind::kBetter);
  EXPECT_EQ(PaperVerdict(PaperRecord("r", 0.0300, 1000, 10), PaperRecord("d", 0.0301, 1005, 10)).kind,
            VerdictKind::kEquivalent);
  EXPECT_EQ(PaperVerdict(PaperRecord("r", 0.04, 1200, 10), PaperRecord("d", 0.03, 1000, 10)).kind, VerdictKind::kWorse);
  EXPECT_EQ(PaperVerdict(PaperRecord("r", 0.02, 1200, 10), PaperRecord("d", 0.03, 1000, 10)).kind, VerdictKind::kMixed);
}

TEST(CandidateSelection, VerdictNamesTheBaseItComparesWith) {
  VerdictOptions options;
  options.base_label = "your configuration (robot.yaml)";
  options.objectives = kPaper;
  const VerdictSummary v = Verdict(PaperRecord("r", 0.04, 1200, 10), PaperRecord("d", 0.03, 1000, 10), options);
  EXPECT_EQ(v.text.rfind("your configuration (robot.yaml) scores better", 0), 0u) << v.text;
  EXPECT_FALSE(v.better());
}

TEST(CandidateSelection, TheConsistencySetRanksByUnbackedHitsNotByMapExtent) {
  // A map broken in two spreads over a larger image, so its eta is lower; its scans disagree
  // with the map (many end points in free cells), so its unbacked-hit share is higher.
  EvaluationRecord sound = PaperRecord("sound", 0.07, 1000, 10), broken = PaperRecord("broken", 0.04, 1000, 10);
  sound.hits = broken.hits = 10000;
  sound.hits_in_free_cells = 300;
  broken.hits_in_free_cells = 1500;
  const std::vector<EvaluationRecord> both{sound, broken};
  const ObjectiveSet consistency{ObjectiveSetKind::kConsistency};
  EXPECT_EQ(both[Worst(both, consistency)].key, "broken");
  EXPECT_EQ(both[Worst(both, kPaper)].key, "sound");
  EXPECT_EQ(Verdict(sound, broken).kind, VerdictKind::kBetter);
  EXPECT_EQ(PaperVerdict(sound, broken).kind, VerdictKind::kWorse);
}

}  // namespace
}  // namespace slamtune::optim
