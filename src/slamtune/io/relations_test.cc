#include "slamtune/io/relations.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <source_location>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/io/testing/read_error.h"

namespace slamtune::io {
namespace {

using slamtune::testing::WriteTempFile;
using ::testing::HasSubstr;

TEST(RelationsTest, ReadsFreiburgLinesAndComments) {
  const std::string path = WriteTempFile("relations_test", "ok",
                                         "# a comment\n\n976052896.784509 976052900.5 1.5 -0.25 0 0 0 0.125\n"
                                         "1 2 0.1 0.2 0.0 0.0 0.0 -3.0\n");
  const auto relations = ReadRelations(path);
  ASSERT_EQ(relations.size(), 2u);
  EXPECT_DOUBLE_EQ(relations[0].t1, 976052896.784509);
  EXPECT_DOUBLE_EQ(relations[0].t2, 976052900.5);
  EXPECT_EQ(relations[0].delta, (Pose2{1.5, -0.25, 0.125}));
  EXPECT_EQ(relations[0].line, 3u);
  EXPECT_EQ(relations[1].delta.theta, -3.0);
  EXPECT_EQ(relations[1].line, 4u);
}

TEST(RelationsTest, ByteOrderMarkDoesNotHideTheFirstRelation) {
  const auto relations = ReadRelations(WriteTempFile("relations_test", "bom",
                                                     "\xEF\xBB\xBF"
                                                     "1 2 0.5 0 0 0 0 0\n2 3 1 0 0 0 0 0\n"));
  ASSERT_EQ(relations.size(), 2u);
  EXPECT_EQ(relations[0].delta.x, 0.5);
  EXPECT_EQ(relations[0].line, 1u);
}

TEST(RelationsTest, RoundTripIsExact) {
  std::vector<Relation> relations = {{1134864643.12418, 1134864650.5, {0.1 + 0.2, -1.0 / 3.0, 2.0 / 7.0}, 0},
                                     {5.0, 6.0, {1e-17, 123456.789, -kPi}, 0}};
  const std::string path = slamtune::testing::TempFilePath("relations_test", "roundtrip");
  WriteRelations(path, relations);
  const auto back = ReadRelations(path);
  ASSERT_EQ(back.size(), relations.size());
  for (std::size_t i = 0; i < back.size(); ++i) {
    EXPECT_EQ(back[i].t1, relations[i].t1);
    EXPECT_EQ(back[i].t2, relations[i].t2);
    EXPECT_EQ(back[i].delta, relations[i].delta);
    EXPECT_EQ(back[i].line, i + 1);
  }
}

TEST(RelationsTest, EmptyFileGivesEmptyList) {
  EXPECT_TRUE(ReadRelations(WriteTempFile("relations_test", "empty", "")).empty());
}

// The error for a file holding `text`, after the file's path.
std::string ErrorFor(const std::string& name, const std::string& text,
                     std::source_location where = std::source_location::current()) {
  return testing::ErrorAfterPath(ReadRelations, "relations_test", name, text, where);
}

TEST(RelationsTest, WrongColumnCountNamesFileAndLine) {
  EXPECT_EQ(ErrorFor("cols", "1 2 0 0 0 0 0 0\n1 2 3\n"),
            ":2: expected 8 columns (t1 t2 x y z roll pitch yaw), found 3");
}

TEST(RelationsTest, NonNumberIsRejected) {
  EXPECT_EQ(ErrorFor("nonnum", "1 2 abc 0 0 0 0 0\n"), ":1: column 3 (x) is not a number: 'abc'");
}

TEST(RelationsTest, NanAndInfAreRejected) {
  EXPECT_EQ(ErrorFor("nan", "1 2 0 0 0 0 0 nan\n"), ":1: column 8 (yaw) is not finite: nan");
  EXPECT_EQ(ErrorFor("inf", "# c\ninf 2 0 0 0 0 0 0\n"), ":2: column 1 (t1) is not finite: inf");
}

TEST(RelationsTest, TruncatedLastLineIsReported) {
  const std::string error = ErrorFor("trunc", "1 2 0 0 0 0 0 0\n3 4 0.5");
  EXPECT_THAT(error, HasSubstr(":2: expected 8 columns"));
  EXPECT_THAT(error, HasSubstr("truncated last line"));
}

TEST(RelationsTest, UnreadableAndUnwritablePathsThrow) {
  EXPECT_THAT([] { ReadRelations("/nonexistent/dir/x.relations"); },
              ::testing::ThrowsMessage<InputError>(HasSubstr("/nonexistent/dir/x.relations: cannot open")));
  EXPECT_THROW(WriteRelations("/nonexistent/dir/x.relations", {}), InputError);
}

}  // namespace
}  // namespace slamtune::io
