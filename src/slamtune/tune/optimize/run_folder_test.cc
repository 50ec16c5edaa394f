#include "slamtune/tune/optimize/run_folder.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/optim/evaluation_store.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

class RunFolderTest : public ::testing::Test {
 protected:
  void SetUp() override { dir_ = testing::UniqueTempDir("run_folder"); }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  // A run folder whose database holds `invocation` (and settings of no interest here).
  std::string FolderWith(const nlohmann::json& invocation) {
    const std::string folder = (dir_ / "run").string();
    std::filesystem::create_directories(folder);
    optim::EvaluationStore((std::filesystem::path(folder) / "run.sqlite").string()).StartRun({{"seed", 1}}, invocation);
    return folder;
  }
  std::string Write(const char* name, const std::string& text) {
    const std::string path = (dir_ / name).string();
    std::ofstream(path) << text;
    return path;
  }

  std::filesystem::path dir_;
};

TEST_F(RunFolderTest, OutAndResumeMustNameOneFolder) {
  EXPECT_THAT([] { RunFolder("", ""); }, ThrowsMessage<InputError>(HasSubstr("--out DIR is required")));
  EXPECT_THAT([] { RunFolder("a", "b"); }, ThrowsMessage<InputError>(HasSubstr("not both")));
  const RunFolder same("a", "a");
  EXPECT_TRUE(same.resume());
  EXPECT_EQ(same.db_path(), "a/run.sqlite");
  EXPECT_FALSE(RunFolder("a", "").resume());
}

TEST_F(RunFolderTest, ANewRunRefusesAFolderHoldingOne) {
  const std::string folder = FolderWith(OptimizeOptions{}.ToJson());
  EXPECT_THAT([&] { RunFolder(folder, "").RefuseHeldRun(); },
              ThrowsMessage<InputError>(HasSubstr("already holds an optimisation")));
  RunFolder fresh((dir_ / "fresh").string(), "");
  EXPECT_NO_THROW(fresh.EnsureLocked());
  EXPECT_TRUE(std::filesystem::is_directory(dir_ / "fresh"));
}

TEST_F(RunFolderTest, ResumeAloneTakesTheRecordedOptions) {
  OptimizeOptions recorded;
  recorded.space = "front-end";
  recorded.budget = {12, 30, 3, 2};
  recorded.seed = 4;
  const std::string folder = FolderWith(recorded.ToJson());
  OptimizeOptions options;  // what the command line gave: nothing that changes results
  PrepareResume(RunFolder("", folder), true, options);
  EXPECT_EQ(options.ToJson(), recorded.ToJson());
}

TEST_F(RunFolderTest, AnOldFolderResumesThroughTheMigration) {
  nlohmann::json oldest = OptimizeOptions{}.ToJson();
  for (const char* key : {"schema", "objectives", "settling", "vary", "fix", "space_probed", "front_end_repair",
                          "around_base_without_steps"}) {
    oldest.erase(key);
  }
  oldest["inputs"].erase("base_rule");
  OptimizeOptions options;
  PrepareResume(RunFolder("", FolderWith(oldest)), true, options);
  EXPECT_EQ(options.objectives, "paper");
  EXPECT_FALSE(options.settling.enabled);
  EXPECT_TRUE(options.around_base_without_steps);
}

TEST_F(RunFolderTest, ChangedInputsAreRefusedAndUnrelatedFilesAreNot) {
  OptimizeOptions recorded;
  recorded.inputs.params_file = Write("params.yaml", "slam_toolbox:\n  ros__parameters:\n    resolution: 0.05\n");
  const std::string folder = FolderWith(InvocationRecord(recorded));
  OptimizeOptions options;
  EXPECT_NO_THROW(PrepareResume(RunFolder("", folder), true, options));
  Write("params.yaml", "slam_toolbox:\n  ros__parameters:\n    resolution: 0.10\n");
  EXPECT_THAT([&] { PrepareResume(RunFolder("", folder), true, options); },
              ThrowsMessage<InputError>(HasSubstr("params.yaml: changed since the run started")));
  // With result-changing options given, those are checked, not the recorded ones.
  OptimizeOptions other;
  other.inputs.params_file = Write("other.yaml", "x: 1\n");
  EXPECT_NO_THROW(PrepareResume(RunFolder("", folder), false, other));
  EXPECT_EQ(other.inputs.params_file, (dir_ / "other.yaml").string());
}

TEST_F(RunFolderTest, ResumeNeedsARunDatabaseWithARecord) {
  std::filesystem::create_directories(dir_ / "empty");
  OptimizeOptions options;
  EXPECT_THAT([&] { PrepareResume(RunFolder("", (dir_ / "empty").string()), true, options); },
              ThrowsMessage<InputError>(HasSubstr("not a slamtune optimisation folder (no run.sqlite)")));
  std::filesystem::create_directories(dir_ / "old");
  optim::EvaluationStore((dir_ / "old" / "run.sqlite").string()).SetSettings({{"seed", 1}});
  const std::string folder = (dir_ / "old").string();
  EXPECT_THAT([&] { PrepareResume(RunFolder("", folder), true, options); },
              ThrowsMessage<InputError>(HasSubstr("holds no command line")));
}

}  // namespace
}  // namespace slamtune::tune
