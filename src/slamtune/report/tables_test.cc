#include "slamtune/report/tables.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"

namespace slamtune::report {
namespace {

TEST(FormatNumber, TenSignificantDigits) {
  EXPECT_EQ(FormatNumber(0.1), "0.1");
  EXPECT_EQ(FormatNumber(1.0 / 3.0), "0.3333333333");
  EXPECT_EQ(FormatNumber(123456789012.0), "1.23456789e+11");
  EXPECT_EQ(FormatNumber(-2.5), "-2.5");
  EXPECT_EQ(FormatNumber(std::numeric_limits<double>::quiet_NaN()), "nan");
  EXPECT_EQ(FormatNumber(-std::numeric_limits<double>::infinity()), "-inf");
}

TEST(CsvField, QuotesOnlyWhenNeeded) {
  EXPECT_EQ(CsvField("plain"), "plain");
  EXPECT_EQ(CsvField(""), "");
  EXPECT_EQ(CsvField("a,b"), "\"a,b\"");
  EXPECT_EQ(CsvField("say \"hi\""), "\"say \"\"hi\"\"\"");
  EXPECT_EQ(CsvField("two\nlines"), "\"two\nlines\"");
  EXPECT_EQ(CsvField("cr\r"), "\"cr\r\"");
  EXPECT_EQ(CsvField(" padded"), "\" padded\"");
}

TEST(CsvTable, WritesHeaderAndRows) {
  CsvTable t;
  t.header = {"label", "value"};
  t.AddRow({"knee", FormatNumber(0.25)});
  t.AddRow({"a, b", "x\"y"});
  EXPECT_EQ(t.ToString(), "label,value\nknee,0.25\n\"a, b\",\"x\"\"y\"\n");
  const auto path = (slamtune::testing::UniqueTempDir("report_table") / "table.csv").string();
  WriteCsv(t, path);
  std::ifstream in(path);
  std::stringstream text;
  text << in.rdbuf();
  EXPECT_EQ(text.str(), t.ToString());
  EXPECT_THROW(WriteCsv(t, "/nonexistent-folder/t.csv"), InputError);
}

TEST(FormatMeanStd, RoundsBothToTheStdsPrecision) {
  EXPECT_EQ(FormatMeanStd(0.012345, 0.004567), "0.0123 \u00b1 0.0046");
  EXPECT_EQ(FormatMeanStd(12.345, 1.5, 2, "+-"), "12.3 +- 1.5");
  EXPECT_EQ(FormatMeanStd(1234.0, 56.0, 1, "+-"), "1234 +- 56");
  EXPECT_EQ(FormatMeanStd(0.5, 0.0, 2, "+-"), "0.5 +- 0");
  EXPECT_EQ(FormatMeanStd(std::numeric_limits<double>::quiet_NaN(), 1.0, 2, "+-"), "nan +- 1");
}

}  // namespace
}  // namespace slamtune::report
