#include "slamtune/common/atomic_file.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "slamtune/common/error.h"

namespace slamtune {
namespace {

namespace fs = std::filesystem;

std::string Slurp(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(AtomicFile, ReplacesTheTargetAndLeavesNoPartialFile) {
  const fs::path dir = fs::temp_directory_path() / ("slamtune_atomic_" + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path target = dir / "out.yaml";
  std::ofstream(target) << "old";
  WriteFileAtomically(target.string(), "new content\n");
  EXPECT_EQ(Slurp(target), "new content\n");
  EXPECT_FALSE(fs::exists(dir / "out.yaml.partial"));
  fs::remove_all(dir);
}

TEST(AtomicFile, UnwritablePlaceIsAnInputErrorNamingThePath) {
  try {
    WriteFileAtomically("/nonexistent-folder/out.yaml", "x");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), ::testing::HasSubstr("/nonexistent-folder/out.yaml: cannot write"));
  }
  const fs::path dir = fs::temp_directory_path() / ("slamtune_atomic_dir_" + std::to_string(getpid()));
  fs::create_directories(dir / "a_folder");
  EXPECT_THROW(WriteFileAtomically((dir / "a_folder").string(), "x"), InputError);  // a folder is not replaced
  EXPECT_TRUE(fs::is_directory(dir / "a_folder"));
  fs::remove_all(dir);
}

}  // namespace
}  // namespace slamtune
