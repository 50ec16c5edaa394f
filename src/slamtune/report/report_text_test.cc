#include "slamtune/report/report_text.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "slamtune/report/testing/fake_optimize_result.h"

namespace slamtune::report {
namespace {

TEST(Readable, RoundsToSignificantDigitsWithoutNoise) {
  EXPECT_EQ(Readable(0.40000000000000002), "0.4");
  EXPECT_EQ(Readable(0.30000000000000004), "0.3");
  EXPECT_EQ(Readable(1234.5678), "1235");
  EXPECT_EQ(Readable(0.0301549), "0.03015");
  EXPECT_EQ(Readable(2851.0), "2851");
  EXPECT_EQ(Readable(12.0), "12");
  EXPECT_EQ(Readable(-0.00001234), "-1.234e-05");
  EXPECT_EQ(Readable(3e9), "3.000e+09");
  EXPECT_EQ(Readable(0.0), "0");
  EXPECT_EQ(Readable(-0.00004, 2, 3), "-4.0e-05");
  EXPECT_EQ(Readable(-0.0004, 2, 3), "0");  // rounded away: no "-0"
  EXPECT_EQ(Readable(3.14159, 9, 3), "3.142");
  EXPECT_EQ(Readable(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(Readable(-std::numeric_limits<double>::infinity()), "-inf");
}

TEST(Readable, DistancesToTheMillimetre) {
  EXPECT_EQ(Metres(2.5), "2.5");
  EXPECT_EQ(Metres(3.14159), "3.142");
  EXPECT_EQ(Metres(123.45678), "123.457");
  EXPECT_EQ(Metres(0.0204), "0.02");
}

TEST(ParamUnit, FromTheParameterTable) {
  EXPECT_EQ(ParamUnit("loop_search_maximum_distance"), "m");
  EXPECT_EQ(ParamUnit("coarse_search_angle_offset"), "rad");
  EXPECT_EQ(ParamUnit("loop_match_minimum_chain_size"), "");       // a count
  EXPECT_EQ(ParamUnit("loop_match_minimum_response_coarse"), "");  // a response
  EXPECT_EQ(ParamUnit("no_such_parameter"), "");
}

TEST(ParamLegend, NamesTheShortSymbolsOnly) {
  EXPECT_EQ(ParamLegend({"loop_search_maximum_distance", "loop_match_minimum_chain_size"}),
            "r = loop_search_maximum_distance (m), g = loop_match_minimum_chain_size");
  // A parameter shown under its ROS name needs no legend.
  EXPECT_EQ(ParamLegend({"correlation_search_space_dimension", "loop_match_minimum_response_coarse"}),
            "p = loop_match_minimum_response_coarse");
  EXPECT_EQ(ParamLegend({"correlation_search_space_dimension", "minimum_travel_distance"}), "");
}

TEST(FormatParam, IntegersPlainOthersRounded) {
  EXPECT_EQ(FormatParam(12.0), "12");
  EXPECT_EQ(FormatParam(0.40000000000000002), "0.4");
  EXPECT_EQ(FormatParam(5.0912345), "5.091");
  EXPECT_EQ(FormatParam(0.0349066), "0.035");
}

TEST(MergedCandidates, OneGroupPerParameterSetInReportOrder) {
  optim::OptimizeResult r = testing::FakeOptimizeResult(false);
  auto groups = MergedCandidates(r);
  ASSERT_EQ(groups.size(), 4u);
  EXPECT_EQ(groups[0].label, "recommended");
  // The knee holds the recommended set: one group, labelled with both.
  r.candidates[1].record = r.candidates[0].record;
  r.candidates[1].map = {};
  groups = MergedCandidates(r);
  ASSERT_EQ(groups.size(), 3u);
  EXPECT_EQ(groups[0].label, "recommended = knee");
  EXPECT_EQ(groups[0].members.size(), 2u);
  EXPECT_EQ(&groups[0].shown(), &r.candidates[0]);  // the member with a map
  EXPECT_EQ(groups[1].label, "default");
  EXPECT_EQ(groups[2].label, "worst");
}

}  // namespace
}  // namespace slamtune::report
