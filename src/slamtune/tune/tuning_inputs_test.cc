#include "slamtune/tune/tuning_inputs.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"
#include "slamtune/common/testing/temp_dir.h"
#include "slamtune/io/carmen/carmen_writer.h"
#include "slamtune/io/relations.h"
#include "slamtune/sim/simulation.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

// A CARMEN log of the built-in office world and its true relations, written once for the suite.
class TuningInputsOnFiles : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new std::filesystem::path(testing::UniqueTempDir("tuning_inputs"));
    sim::Simulation s = sim::Simulate(sim::SimulationOptions{});
    io::WriteCarmenLog((*dir_ / "office.clf").string(), s.log);
    io::WriteRelations((*dir_ / "office.relations").string(), s.relations);
    scans_ = s.log.scans.size();
    relations_ = s.relations.size();
  }
  static void TearDownTestSuite() {
    std::filesystem::remove_all(*dir_);
    delete dir_;
  }
  static std::string File(const char* name) { return (*dir_ / name).string(); }

  static std::filesystem::path* dir_;
  static std::size_t scans_, relations_;
};
std::filesystem::path* TuningInputsOnFiles::dir_ = nullptr;
std::size_t TuningInputsOnFiles::scans_ = 0, TuningInputsOnFiles::relations_ = 0;

TEST_F(TuningInputsOnFiles, ALogItsRelationsAndAPresetLoadTogether) {
  TuningInputOptions o;
  o.log = File("office.clf");
  o.relations = File("office.relations");
  o.preset = "slam_toolbox_sync";
  o.sets = {"loop_search_maximum_distance=6"};
  o.input.max_scans = 300;
  const TuningInputs in = LoadTuningInputs(o, InputNotes::kNone);
  ASSERT_NE(in.log, nullptr);
  EXPECT_EQ(in.log->scans.size(), 300u);
  EXPECT_EQ(in.source.log_label, o.log);
  EXPECT_EQ(in.source.relations_label, o.relations);
  EXPECT_EQ(in.relations.size(), relations_);
  EXPECT_EQ(in.base.node_mode, slam::NodeMode::kSlamToolboxSync);
  EXPECT_EQ(in.base.loop_search_maximum_distance, 6.0);
  EXPECT_EQ(in.base_node, slam::RosNode::kSlamToolbox);
}

TEST_F(TuningInputsOnFiles, TheOutputCheckRunsAfterTheBaseAndRelationsBeforeTheLog) {
  TuningInputOptions o;
  o.log = File("office.clf");
  o.input.max_scans = 50;
  int calls = 0;
  o.sets = {"no_such_parameter=1"};
  EXPECT_THROW(LoadTuningInputs(o, InputNotes::kNone, [&] { ++calls; }), InputError);
  o.sets.clear();
  o.relations = File("missing.relations");
  EXPECT_THROW(LoadTuningInputs(o, InputNotes::kNone, [&] { ++calls; }), InputError);
  EXPECT_EQ(calls, 0);
  o.relations.clear();
  o.log = File("missing.clf");
  EXPECT_THROW(LoadTuningInputs(o, InputNotes::kNone, [&] { ++calls; }), InputError);
  EXPECT_EQ(calls, 1);  // called, then the log failed
  o.log = File("office.clf");
  EXPECT_THAT([&] { LoadTuningInputs(o, InputNotes::kNone, [] { throw InputError("out: not writable"); }); },
              ThrowsMessage<InputError>(HasSubstr("out: not writable")));
}

TEST_F(TuningInputsOnFiles, RelationsOfAnotherLogAreRefused) {
  // Relations whose stamps lie before the log's first scan match none of its scans.
  std::vector<io::Relation> far = io::ReadRelations(File("office.relations"));
  for (io::Relation& r : far) {
    r.t1 -= 1e6;
    r.t2 -= 1e6;
  }
  io::WriteRelations(File("far.relations"), far);
  TuningInputOptions o;
  o.log = File("office.clf");
  o.relations = File("far.relations");
  EXPECT_THAT([&] { LoadTuningInputs(o, InputNotes::kNone); },
              ThrowsMessage<InputError>(HasSubstr(File("far.relations"))));
}

TEST(TuningInputs, WithoutALogTheWorldIsSimulatedWithItsTrueRelations) {
  TuningInputOptions o;
  o.world = "office";
  o.world_seed = 2;
  const TuningInputs in = LoadTuningInputs(o, InputNotes::kNone);
  EXPECT_EQ(in.source.log_label, "built-in world office (seed 2)");
  EXPECT_EQ(in.source.relations_label, "simulated (true trajectory)");
  EXPECT_FALSE(in.relations.empty());
  EXPECT_EQ(in.base_label, "slam_karto's defaults");
  EXPECT_EQ(in.base.node_mode, slam::NodeMode::kSlamKarto);
}

TEST(TuningInputs, ASliceOrAnUnknownWorldIsRefusedBeforeAnythingIsRead) {
  TuningInputOptions o;
  o.params_file = "/nonexistent/params.yaml";  // not read: the world's check comes first
  o.input.max_scans = 10;
  EXPECT_THAT([&] { LoadTuningInputs(o, InputNotes::kNone); }, ThrowsMessage<InputError>(HasSubstr("--max-scans 10")));
  o.input.max_scans = 0;
  o.world = "atlantis";
  EXPECT_THAT([&] { LoadTuningInputs(o, InputNotes::kNone); }, ThrowsMessage<InputError>(HasSubstr("atlantis")));
}

TEST(TuningInputOptions, JsonKeepsEverythingThatChangesResults) {
  TuningInputOptions o;
  o.log = "a.clf";
  o.relations = "a.relations";
  o.world = "corridor-long";
  o.world_seed = 7;
  o.preset = "slam_toolbox";
  o.params_file = "p.yaml";
  o.sets = {"r=3", "g=9"};
  o.base_rule = slam::BaseRule::kPresetThenFile;
  o.input.beams = "nearest-beam";
  const TuningInputOptions back = TuningInputOptions::FromJson(o.ToJson());
  EXPECT_EQ(back.ToJson(), o.ToJson());
  EXPECT_EQ(back.base_rule, slam::BaseRule::kPresetThenFile);

  EXPECT_EQ(TuningInputOptions::FromJson(TuningInputOptions{}.ToJson()).base_rule, slam::BaseRule::kNodeDefaults);
}

TEST(TuningRunOptions, JobsMustBePositiveAndSharingNeedsABudget) {
  TuningRunOptions run;
  EXPECT_GE(run.jobs, 1);
  run.jobs = 0;
  EXPECT_THAT([&] { run.Validate(); }, ThrowsMessage<InputError>(HasSubstr("--jobs = 0")));
  run.jobs = 1;
  run.share_mb = 0;
  optim::SlamEvaluationContext context;
  EXPECT_THAT([&] { ShareWork(context, run); }, ThrowsMessage<InputError>(HasSubstr("--share-mb = 0")));
  run.no_share = true;
  EXPECT_NO_THROW(ShareWork(context, run));
  EXPECT_EQ(context.shared_work.match_cache, nullptr);
}

TEST(OutputFolder, AFolderThatCannotBeCreatedIsNamed) {
  const std::filesystem::path dir = testing::UniqueTempDir("output_folder");
  std::ofstream(dir / "file") << "x";
  const std::string inside_file = (dir / "file" / "out").string();
  EXPECT_THAT([&] { EnsureWritableOutputFolder(inside_file); },
              ThrowsMessage<InputError>(HasSubstr("cannot create output folder")));
  EXPECT_NO_THROW(EnsureWritableOutputFolder((dir / "a" / "b").string()));
  EXPECT_TRUE(std::filesystem::is_directory(dir / "a" / "b"));
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace slamtune::tune
