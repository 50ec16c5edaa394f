#include "slamtune/common/output_dir.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"

namespace slamtune {
namespace {

namespace fs = std::filesystem;
using slamtune::testing::ErrorMessageOf;

TEST(EnsureOutputDir, CreatesMissingFoldersAndLeavesNoProbe) {
  const fs::path dir = fs::path(::testing::TempDir()) / "output_dir_test" / "a" / "b";
  fs::remove_all(dir.parent_path().parent_path());
  EnsureOutputDir(dir.string());
  EXPECT_TRUE(fs::is_directory(dir));
  EXPECT_TRUE(fs::is_empty(dir));
  EnsureOutputDir(dir.string());  // an existing folder is fine
}

TEST(EnsureOutputDir, RefusesAFileAnEmptyNameAndProcWithOneLine) {
  const std::string file = (fs::path(::testing::TempDir()) / "output_dir_test_file").string();
  std::ofstream(file) << "x";
  EXPECT_EQ(ErrorMessageOf([&] { EnsureOutputDir(file); }), file + ": cannot create output folder: is a file");
  EXPECT_EQ(ErrorMessageOf([&] { EnsureOutputDir(file + "/sub"); }),
            file + "/sub: cannot create output folder: Not a directory");
  EXPECT_EQ(ErrorMessageOf([] { EnsureOutputDir(""); }), "--out: empty folder name; give the folder to write to");
  EXPECT_THAT(
      [] { EnsureOutputDir("/proc/slamtune_out"); },
      ::testing::ThrowsMessage<InputError>(::testing::StartsWith("/proc/slamtune_out: cannot create output folder: ")));
}

}  // namespace
}  // namespace slamtune
