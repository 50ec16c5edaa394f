#include "slamtune/common/output_dir.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "slamtune/common/error.h"

namespace slamtune {
namespace {

namespace fs = std::filesystem;

std::string ErrorOf(const std::string& dir) {
  try {
    EnsureOutputDir(dir);
  } catch (const InputError& e) {
    return e.what();
  }
  return "no error";
}

TEST(EnsureOutputDir, CreatesMissingFoldersAndLeavesNoProbe) {
  const fs::path dir = fs::path(testing::TempDir()) / "output_dir_test" / "a" / "b";
  fs::remove_all(dir.parent_path().parent_path());
  EnsureOutputDir(dir.string());
  EXPECT_TRUE(fs::is_directory(dir));
  EXPECT_TRUE(fs::is_empty(dir));
  EnsureOutputDir(dir.string());  // an existing folder is fine
}

TEST(EnsureOutputDir, RefusesAFileAnEmptyNameAndProcWithOneLine) {
  const std::string file = (fs::path(testing::TempDir()) / "output_dir_test_file").string();
  std::ofstream(file) << "x";
  EXPECT_EQ(ErrorOf(file), file + ": cannot create output folder: is a file");
  EXPECT_EQ(ErrorOf(file + "/sub"), file + "/sub: cannot create output folder: Not a directory");
  EXPECT_EQ(ErrorOf(""), "--out: empty folder name; give the folder to write to");
  EXPECT_EQ(ErrorOf("/proc/slamtune_out").rfind("/proc/slamtune_out: cannot create output folder: ", 0), 0u);
}

}  // namespace
}  // namespace slamtune
