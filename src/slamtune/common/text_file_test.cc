#include "slamtune/common/text_file.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"

namespace slamtune {
namespace {

namespace fs = std::filesystem;
using slamtune::testing::ErrorMessageOf;

std::string TempPath(const std::string& name) { return (fs::path(::testing::TempDir()) / name).string(); }

void Write(const std::string& path, const std::string& bytes) { std::ofstream(path, std::ios::binary) << bytes; }

TEST(ReadTextFile, ReadsTheWholeFileAndStripsAByteOrderMark) {
  const std::string plain = TempPath("text_file_plain.yaml");
  Write(plain, "a: 1\nb: 2\n");
  EXPECT_EQ(ReadTextFile(plain), "a: 1\nb: 2\n");
  const std::string bom = TempPath("text_file_bom.yaml");
  Write(bom,
        "\xEF\xBB\xBF"
        "a: 1\n");
  EXPECT_EQ(ReadTextFile(bom), "a: 1\n");
  EXPECT_EQ(ReadWholeFile(bom),
            "\xEF\xBB\xBF"
            "a: 1\n");  // bytes as they are
}

TEST(ReadTextFile, RefusesDirectoriesMissingAndEmptyPaths) {
  const std::string dir = TempPath("text_file_dir");
  fs::create_directories(dir);
  EXPECT_EQ(ErrorMessageOf([&] { ReadTextFile(dir); }), dir + ": cannot open: is a directory");
  EXPECT_EQ(ErrorMessageOf([&] { ReadTextFile(dir + "/absent.yaml"); }),
            dir + "/absent.yaml: cannot open: no such file");
  EXPECT_EQ(ErrorMessageOf([] { ReadTextFile(""); }), "empty file name: a file to read is required");
}

TEST(StripUtf8Bom, RemovesOnlyALeadingMark) {
  EXPECT_EQ(StripUtf8Bom("\xEF\xBB\xBFx"), "x");
  EXPECT_EQ(StripUtf8Bom("x\xEF\xBB\xBF"), "x\xEF\xBB\xBF");
  EXPECT_EQ(StripUtf8Bom("\xEF\xBB"), "\xEF\xBB");
}

}  // namespace
}  // namespace slamtune
