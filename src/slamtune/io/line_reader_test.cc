#include "slamtune/io/line_reader.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <zlib.h>

#include <cmath>
#include <sstream>

#include "slamtune/common/error.h"

namespace slamtune::io {
namespace {

std::vector<std::string> AllLines(LineReader& reader, bool* last_unterminated = nullptr) {
  std::vector<std::string> lines;
  std::string_view line;
  while (reader.Next(&line)) {
    lines.emplace_back(line);
    if (last_unterminated != nullptr) *last_unterminated = reader.unterminated();
  }
  return lines;
}

std::string Gzip(const std::string& text) {
  uLongf size = compressBound(static_cast<uLong>(text.size())) + 64;
  std::string out(size, '\0');
  z_stream zs{};
  EXPECT_EQ(deflateInit2(&zs, 6, Z_DEFLATED, 15 + 16, 8, Z_DEFAULT_STRATEGY), Z_OK);
  zs.next_in = reinterpret_cast<Bytef*>(const_cast<char*>(text.data()));
  zs.avail_in = static_cast<uInt>(text.size());
  zs.next_out = reinterpret_cast<Bytef*>(out.data());
  zs.avail_out = static_cast<uInt>(out.size());
  EXPECT_EQ(deflate(&zs, Z_FINISH), Z_STREAM_END);
  out.resize(zs.total_out);
  deflateEnd(&zs);
  return out;
}

// Lines of varied length whose total is several times the 1 MiB read chunk.
std::string ManyLines(std::size_t count) {
  std::string text;
  for (std::size_t i = 0; i < count; ++i)
    text += std::string(i % 977, 'a' + static_cast<char>(i % 26)) + "|" + std::to_string(i) + "\n";
  return text;
}

TEST(LineReaderTest, LinesAcrossChunkBoundariesPlainAndGzip) {
  const std::string text = ManyLines(9000);  // about 4.4 MB
  for (const bool compressed : {false, true}) {
    std::istringstream in(compressed ? Gzip(text) : text);
    LineReader reader(&in, "mem");
    bool unterminated = true;
    const auto lines = AllLines(reader, &unterminated);
    EXPECT_EQ(reader.compressed(), compressed);
    ASSERT_EQ(lines.size(), 9000u);
    for (std::size_t i = 0; i < lines.size(); i += 7) {
      ASSERT_EQ(lines[i], std::string(i % 977, 'a' + static_cast<char>(i % 26)) + "|" + std::to_string(i)) << i;
    }
    EXPECT_FALSE(unterminated);
    EXPECT_EQ(reader.line_number(), 9000u);
  }
}

TEST(LineReaderTest, UnterminatedLastLineAfterARefill) {
  const std::string text = ManyLines(3000) + "last line without newline";
  std::istringstream in(text);
  LineReader reader(&in, "mem");
  bool unterminated = false;
  const auto lines = AllLines(reader, &unterminated);
  ASSERT_EQ(lines.size(), 3001u);
  EXPECT_EQ(lines.back(), "last line without newline");
  EXPECT_TRUE(unterminated);
}

TEST(LineReaderTest, LongUnterminatedLastLineAfterAShortOne) {
  // The last line is longer than what precedes it, so moving it to the buffer front overlaps.
  const std::string last = std::string(5000, 'y') + " end";
  std::istringstream in("# short\n" + last);
  LineReader reader(&in, "mem");
  const auto lines = AllLines(reader);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[1], last);
}

TEST(LineReaderTest, CrLfEmptyLinesAndALineLongerThanTheBuffer) {
  const std::string huge(3u << 20, 'x');
  std::istringstream in("a b\r\n\n" + huge + "\nend");
  LineReader reader(&in, "mem");
  const auto lines = AllLines(reader);
  ASSERT_EQ(lines.size(), 4u);
  EXPECT_EQ(lines[0], "a b");
  EXPECT_EQ(lines[1], "");
  EXPECT_EQ(lines[2].size(), huge.size());
  EXPECT_EQ(lines[3], "end");
}

TEST(LineReaderTest, ByteOrderMarkBeforeTheFirstLineIsDroppedPlainAndGzip) {
  const std::string text =
      "\xEF\xBB\xBF"
      "FLASER 1 2\n\xEF\xBB\xBF"
      "kept\n";
  for (const std::string& bytes : {text, Gzip(text)}) {
    std::istringstream in(bytes);
    LineReader reader(&in, "bom");
    const auto lines = AllLines(reader);
    ASSERT_EQ(lines.size(), 2u);
    EXPECT_EQ(lines[0], "FLASER 1 2");
    EXPECT_EQ(lines[1],
              "\xEF\xBB\xBF"
              "kept");  // only the file's start carries a mark
  }
}

TEST(LineReaderTest, TruncatedGzipNamesTheLineBeingRead) {
  const std::string gz = Gzip(ManyLines(4000));
  std::istringstream in(gz.substr(0, gz.size() / 2));
  LineReader reader(&in, "x.gz");
  try {
    AllLines(reader);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::StartsWith("x.gz:"));
    EXPECT_THAT(e.what(), ::testing::HasSubstr("truncated gzip stream"));
    EXPECT_GT(e.line(), 100u);
  }
}

TEST(LineReaderTest, SplitAndParse) {
  std::vector<std::string_view> fields;
  SplitFields("  FLASER\t3  1.5 -2e-3 ", &fields);
  EXPECT_THAT(fields, ::testing::ElementsAre("FLASER", "3", "1.5", "-2e-3"));
  EXPECT_EQ(ParseDouble("+1.25"), 1.25);
  EXPECT_EQ(ParseDouble("-2e-3"), -0.002);
  EXPECT_TRUE(std::isnan(*ParseDouble("nan")));
  EXPECT_TRUE(std::isinf(*ParseDouble("-inf")));
  EXPECT_FALSE(ParseDouble("1.5x"));
  EXPECT_FALSE(ParseDouble(""));
  EXPECT_FALSE(ParseDouble("++1"));
  EXPECT_EQ(ParseCount("180"), 180u);
  EXPECT_FALSE(ParseCount("-1"));
  EXPECT_FALSE(ParseCount("1.5"));
  for (const double v : {0.1, 976052857.337284, -1.0 / 3.0, 1e-300}) EXPECT_EQ(*ParseDouble(FormatExact(v)), v);
}

}  // namespace
}  // namespace slamtune::io
