#include "slamtune/slam/params/mapper_param_rows.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(MapperParamRows, EveryParameterOnceInTableOrder) {
  const std::vector<ParamRow>& rows = ParamRows();
  const std::vector<ParamInfo>& table = ParamTable();
  ASSERT_EQ(rows.size(), table.size());
  std::set<std::string> names;
  for (std::size_t i = 0; i < rows.size(); ++i) {
    EXPECT_STREQ(rows[i].info.name, table[i].name);
    EXPECT_TRUE(names.insert(rows[i].info.name).second) << rows[i].info.name;
    EXPECT_EQ(FindParamRow(rows[i].info.name), &rows[i]);
  }
  EXPECT_STREQ(rows.front().info.name, "use_scan_matching");
  EXPECT_STREQ(rows.back().info.name, "matcher_threads");
  EXPECT_EQ(FindParamRow("loop_search_radius"), nullptr);
}

TEST(MapperParamRows, ChoicesOnlyForTextParameters) {
  for (const ParamRow& row : ParamRows()) {
    EXPECT_EQ(row.info.type == ParamType::kString, !row.choices.empty()) << row.info.name;
  }
  const ParamRow* solver = FindParamRow("solver");
  ASSERT_NE(solver, nullptr);
  EXPECT_EQ(solver->choices, (std::vector<std::string>{"spa", "ceres"}));
}

TEST(MapperParamRows, BoundsAreOpenOrClosedAsWritten) {
  const ParamBounds above_zero{0.0, true, 1.0, false};
  EXPECT_FALSE(InParamBounds(0.0, above_zero));
  EXPECT_TRUE(InParamBounds(1e-300, above_zero));
  EXPECT_TRUE(InParamBounds(1.0, above_zero));
  EXPECT_FALSE(InParamBounds(std::nextafter(1.0, 2.0), above_zero));
  EXPECT_FALSE(InParamBounds(std::nan(""), ParamBounds{}));
  EXPECT_FALSE(InParamBounds(INFINITY, ParamBounds{}));
  EXPECT_TRUE(InParamBounds(-1e300, ParamBounds{}));
}

TEST(MapperParamRows, ValuesReadAndShownAsMessagesGiveThem) {
  MapperParams p;
  p.solver = SolverKind::kCeres;
  EXPECT_EQ(ReadParamValue(p, FindParamRow("solver")->member), ParamValue(std::string("ceres")));
  EXPECT_EQ(ReadParamValue(p, FindParamRow("scan_buffer_size")->member), ParamValue(70));
  EXPECT_EQ(FormatParamValue(ReadParamValue(p, FindParamRow("do_loop_closing")->member)), "true");
  EXPECT_EQ(FormatParamValue(std::string("ceres")), "'ceres'");
  EXPECT_EQ(FormatParamValue(0.05), "0.05");
}

TEST(MapperParamRows, ValuesAsAListingWritesThem) {
  EXPECT_EQ(ParamValueText(std::string("ceres")), "ceres");
  EXPECT_EQ(ParamValueText(false), "false");
  EXPECT_EQ(ParamValueText(70), "70");
  EXPECT_EQ(ParamValueText(0.1), "0.1");
  EXPECT_EQ(ParamValueText(1e-7), "1e-07");
}

TEST(MapperParamRows, TheCheckOfARowNamesItsRule) {
  MapperParams p;
  const ParamRow& resolution = *FindParamRow("resolution");
  EXPECT_NO_THROW(CheckParamRow(p, resolution));
  p.resolution = 0.0;
  EXPECT_THAT([&] { CheckParamRow(p, resolution); },
              ThrowsMessage<InputError>(HasSubstr("mapper parameter resolution = 0 is out of range: must be > 0")));
  p = {};
  p.minimum_angle_penalty = 1.0;  // the closed end
  EXPECT_NO_THROW(CheckParamRow(p, *FindParamRow("minimum_angle_penalty")));
  p.minimum_angle_penalty = 1.5;
  EXPECT_THAT([&] { CheckParamRow(p, *FindParamRow("minimum_angle_penalty")); },
              ThrowsMessage<InputError>(HasSubstr("minimum_angle_penalty = 1.5 is out of range: must be in [0, 1]")));
  p.use_scan_matching = false;  // any bool
  EXPECT_NO_THROW(CheckParamRow(p, *FindParamRow("use_scan_matching")));
}

}  // namespace
}  // namespace slamtune::slam
