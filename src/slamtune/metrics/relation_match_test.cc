#include "slamtune/metrics/relation_match.h"

#include <gtest/gtest.h>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"

namespace slamtune::metrics {
namespace {

using slamtune::testing::ErrorMessageOf;

io::LaserLog LogWithScansAt(const std::vector<double>& times) {
  io::LaserLog log;
  for (const double t : times) {
    io::LaserScanRecord scan;
    scan.ipc_time = t;
    log.scans.push_back(scan);
  }
  return log;
}

io::Relation Rel(double t1, double t2) { return {t1, t2, Pose2{}, 0}; }

// The message with which the relations of "truth.relations" are refused for `log`.
std::string MessageOf(const io::LaserLog& log, const std::vector<io::Relation>& relations) {
  return ErrorMessageOf([&] { RequireMatchingRelations(log, relations, "truth.relations"); });
}

TEST(RelationMatch, CountsRelationsWithBothTimestampsAtScans) {
  const RelationMatch match =
      MatchRelations({3.0, 1.0, 2.0}, {Rel(1.0, 2.0), Rel(1.0, 2.5), Rel(2.000001, 3.0), Rel(7.0, 8.0)});
  EXPECT_EQ(match.total, 4u);
  EXPECT_EQ(match.matching, 2u);  // within the 1e-5 s tolerance of gt_error
  EXPECT_FALSE(match.complete());
  EXPECT_EQ(match.Brief(), "2 of 4 relations match scans of the log");
}

TEST(RelationMatch, PartialMatchIsCountedNotRefused) {
  const RelationMatch match = RequireMatchingRelations(LogWithScansAt({1, 2, 3}), {Rel(1, 2), Rel(2, 9)}, "f");
  EXPECT_EQ(match.matching, 1u);
  EXPECT_EQ(match.total, 2u);
}

TEST(RelationMatch, NoMatchIsRefusedNamingTheFileAndBothSpans) {
  EXPECT_EQ(MessageOf(LogWithScansAt({10, 12.5, 11}), {Rel(100, 101), Rel(99.5, 10)}),
            "truth.relations: no relation's timestamps match a scan of the log (the log's scans span 10.000 .. "
            "12.500 s; the 2 relations span 10.000 .. 101.000 s)");
}

TEST(RelationMatch, EmptyFileOrLogIsRefused) {
  EXPECT_EQ(MessageOf(LogWithScansAt({1}), {}), "truth.relations: no relations in the file");
  EXPECT_EQ(MessageOf(LogWithScansAt({}), {Rel(1, 2)}),
            "truth.relations: no relation's timestamps match a scan of the log (the log has no scans; the "
            "relation spans 1.000 .. 2.000 s)");
}

}  // namespace
}  // namespace slamtune::metrics
