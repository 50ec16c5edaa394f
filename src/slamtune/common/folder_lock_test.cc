#include "slamtune/common/folder_lock.h"

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <memory>
#include <string>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"

namespace slamtune {
namespace {

using slamtune::testing::ErrorMessageOf;

std::string FreshDir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() / ("slamtune_lock_" + name);
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir.string();
}

// The message with which a second lock of `dir` is refused.
std::string Refusal(const std::string& dir) {
  return ErrorMessageOf([&] { FolderLock second(dir); });
}

TEST(FolderLock, SecondHolderIsRefusedNamingFolderAndPid) {
  const std::string dir = FreshDir("held");
  FolderLock first(dir);
  EXPECT_EQ(Refusal(dir), dir + ": another slamtune process (pid " + std::to_string(getpid()) +
                              ") is working in this folder; wait for it to end or stop it");
  std::ifstream file(first.path());
  std::string pid;
  file >> pid;
  EXPECT_EQ(pid, std::to_string(getpid()));
}

TEST(FolderLock, ReleasedWhenTheHolderEnds) {
  const std::string dir = FreshDir("released");
  { FolderLock first(dir); }
  EXPECT_NO_THROW(FolderLock second(dir));
}

TEST(FolderLock, AnotherProcessIsRefused) {
  const std::string dir = FreshDir("process");
  auto lock = std::make_unique<FolderLock>(dir);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) _exit(Refusal(dir).find("(pid " + std::to_string(getppid()) + ")") != std::string::npos ? 0 : 1);
  int status = 0;
  waitpid(child, &status, 0);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0);
}

TEST(FolderLock, MissingFolderIsAnInputError) {
  const std::string dir = FreshDir("missing") + "/not_there";
  EXPECT_THROW(FolderLock lock(dir), InputError);
}

}  // namespace
}  // namespace slamtune
