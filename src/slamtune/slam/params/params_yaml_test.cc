#include "slamtune/slam/params/params_yaml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <initializer_list>
#include <string>
#include <string_view>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"
#include "slamtune/slam/params/ros_node_files.h"

namespace slamtune::slam {
namespace {

using slamtune::testing::ErrorMessageOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(ParamsYaml, ReadsRos2Nesting) {
  MapperParams p;
  const auto report = ApplyParamsYaml(p,
                                      "slam_toolbox:\n"
                                      "  ros__parameters:\n"
                                      "    solver_plugin: solver_plugins::CeresSolver\n"
                                      "    odom_frame: odom\n"
                                      "    loop_search_maximum_distance: 3.0\n"
                                      "    loop_match_minimum_chain_size: 6\n"
                                      "    use_response_expansion: true\n"
                                      "    map_start_pose: [0.0, 0.0, 0.0]\n",
                                      "test.yaml");
  EXPECT_EQ(p.solver, SolverKind::kCeres);
  EXPECT_EQ(p.loop_search_maximum_distance, 3.0);
  EXPECT_EQ(p.loop_match_minimum_chain_size, 6);
  EXPECT_TRUE(p.use_response_expansion);
  EXPECT_THAT(report.applied, ElementsAre("solver", "loop_search_maximum_distance", "loop_match_minimum_chain_size",
                                          "use_response_expansion"));
  EXPECT_THAT(report.ignored, ElementsAre("odom_frame", "map_start_pose"));
}

TEST(ParamsYaml, ReadsFlatSlamKartoFile) {
  MapperParams p;
  ApplyParamsYaml(p,
                  "use_scan_matching: true\n"
                  "minimum_travel_heading: 0.2\n"
                  "loop_match_maximum_variance_coarse: 0.5\n"
                  "delta: 0.025\n",
                  "mapper_params.yaml");
  EXPECT_EQ(p.minimum_travel_heading, 0.2);
  EXPECT_EQ(p.loop_match_maximum_variance_coarse, 0.5);
  EXPECT_EQ(p.resolution, 0.025);  // `delta` is slam_karto's fallback name
}

TEST(ParamsYaml, BareRosParametersAndEmptyFile) {
  MapperParams p;
  ApplyParamsYaml(p, "ros__parameters:\n  scan_buffer_size: 12\n", "x.yaml");
  EXPECT_EQ(p.scan_buffer_size, 12);
  const MapperParams before = p;
  ApplyParamsYaml(p, "", "empty.yaml");
  EXPECT_EQ(p, before);
}

TEST(ParamsYaml, RejectsUnknownWrongTypeAndOutOfRange) {
  MapperParams p;
  const MapperParams before = p;
  EXPECT_THAT([&] { ApplyParamsYaml(p, "loop_search_radius: 3\n", "test.yaml"); },
              ThrowsMessage<InputError>(HasSubstr("test.yaml:1: unknown mapper parameter 'loop_search_radius'")));
  EXPECT_THAT([&] { ApplyParamsYaml(p, "scan_buffer_size: 10\nloop_match_minimum_chain_size: many\n", "test.yaml"); },
              ThrowsMessage<InputError>(
                  HasSubstr("test.yaml:2: mapper parameter loop_match_minimum_chain_size = 'many' is not a number")));
  EXPECT_THAT([&] { ApplyParamsYaml(p, "loop_match_minimum_response_coarse: 1.5\n", "test.yaml"); },
              ThrowsMessage<InputError>(
                  HasSubstr("loop_match_minimum_response_coarse = 1.5 is out of range: must be in [0, 1]")));
  EXPECT_THAT([&] { ApplyParamsYaml(p, "loop_search_maximum_distance: [1, 2]\n", "test.yaml"); },
              ThrowsMessage<InputError>(HasSubstr("must be a scalar")));
  EXPECT_THAT([&] { ApplyParamsYaml(p, "solver_plugin: solver_plugins::G2oSolver\n", "test.yaml"); },
              ThrowsMessage<InputError>(HasSubstr("is not supported")));
  // A choice that names none is reported after the last key, as the first value out of range in table order.
  EXPECT_EQ(ErrorMessageOf([&] { ApplyParamsYaml(p, "ceres_loss_function: SoftL1\nresolution: -1\n", "test.yaml"); }),
            "test.yaml: mapper parameter resolution = -1 is out of range: must be > 0");
  EXPECT_EQ(ErrorMessageOf([&] { ApplyParamsYaml(p, "ceres_loss_function: SoftL1\n", "test.yaml"); }),
            "test.yaml: mapper parameter ceres_loss_function = 'SoftL1' is out of range: must be None, HuberLoss or "
            "CauchyLoss");
  EXPECT_THAT([&] { ApplyParamsYaml(p, "a: [\n", "test.yaml"); }, ThrowsMessage<InputError>(HasSubstr("test.yaml:")));
  EXPECT_EQ(p, before);  // nothing applied on error
}

TEST(ParamsYaml, KeysThatAreNotTextAreInputErrorsAndARepeatedNodeKeyIsRead) {
  MapperParams p;
  EXPECT_EQ(ErrorMessageOf([&] { ApplyParamsYaml(p, "{a: 1}: 2\n", "test.yaml"); }),
            "test.yaml:1: a parameter name must be plain text, not a YAML map");
  EXPECT_EQ(ErrorMessageOf([&] { ApplyParamsYaml(p, "[x]:\n  ros__parameters: {}\n", "test.yaml"); }),
            "test.yaml:1: a node name must be plain text, not a YAML sequence");
  // The node key written twice: the entry that holds ros__parameters is read, whichever comes
  // first (a lookup by key would take the first and find no ros__parameters in it).
  const std::string twice =
      "slam_toolbox: 1\n"
      "slam_toolbox:\n"
      "  ros__parameters:\n"
      "    loop_search_maximum_distance: 3.5\n";
  EXPECT_NO_THROW(ApplyParamsYaml(p, twice, "test.yaml"));
  EXPECT_EQ(p.loop_search_maximum_distance, 3.5);
}

TEST(ParamsYaml, AConsistentMatcherSetIsTakenInAnyOrder) {
  MapperParams p;
  ApplyParamsYaml(p,
                  "correlation_search_space_dimension: 0.6\ncorrelation_search_space_resolution: 0.1\n"
                  "correlation_search_space_smear_deviation: 0.2\n",
                  "matcher.yaml");
  EXPECT_EQ(p.correlation_search_space_dimension, 0.6);
  EXPECT_EQ(p.correlation_search_space_resolution, 0.1);
}

// A slam_toolbox parameter file holding `lines` ("key: value"), one a line.
std::string ToolboxYaml(std::initializer_list<std::string_view> lines) {
  std::string yaml = "slam_toolbox:\n  ros__parameters:\n";
  for (const std::string_view line : lines) yaml.append("    ").append(line).append("\n");
  return yaml;
}

const KeyReport& KeyOf(const ParamsYamlReport& report, const std::string& key) {
  for (const KeyReport& k : report.keys) {
    if (k.key == key) return k;
  }
  throw std::runtime_error("no key " + key);
}

TEST(ParamsYaml, CeresKeysAreReadAsTheNodeMapsThem) {
  MapperParams p = NodeDefaults(RosNode::kSlamToolbox);
  const ParamsYamlReport r = ApplyParamsYaml(p,
                                             ToolboxYaml({
                                                 "ceres_linear_solver: SPARSE_SCHUR",
                                                 "ceres_preconditioner: IDENTITY",
                                                 "ceres_trust_strategy: DOGLEG",
                                                 "ceres_dogleg_type: SUBSPACE_DOGLEG",
                                                 "ceres_loss_function: HuberLoss",
                                             }),
                                             "toolbox.yaml");
  EXPECT_EQ(p.ceres_linear_solver, CeresLinearSolver::kSparseSchur);
  EXPECT_EQ(p.ceres_preconditioner, CeresPreconditioner::kIdentity);
  EXPECT_EQ(p.ceres_trust_strategy, CeresTrustStrategy::kDogleg);
  EXPECT_EQ(p.ceres_dogleg_type, CeresDoglegType::kSubspace);
  EXPECT_EQ(p.ceres_loss_function, CeresLoss::kHuber);
  EXPECT_TRUE(r.warnings.empty());
  for (const KeyReport& k : r.keys) EXPECT_EQ(k.use, KeyUse::kEngine) << k.key;

  // A text the node does not know is its default, said in a warning naming file and line.
  MapperParams q = NodeDefaults(RosNode::kSlamToolbox);
  q.ceres_trust_strategy = CeresTrustStrategy::kDogleg;
  const ParamsYamlReport unknown = ApplyParamsYaml(
      q, ToolboxYaml({"ceres_linear_solver: DENSE_QR", "ceres_trust_strategy: LM", "ceres_loss_function: SoftL1"}),
      "toolbox.yaml");
  EXPECT_EQ(q.ceres_linear_solver, CeresLinearSolver::kSparseNormalCholesky);
  EXPECT_EQ(q.ceres_trust_strategy, CeresTrustStrategy::kLevenbergMarquardt);  // "LM", its declared default
  EXPECT_EQ(q.ceres_loss_function, CeresLoss::kNone);
  EXPECT_THAT(unknown.warnings,
              ElementsAre("toolbox.yaml:3: ceres_linear_solver: 'DENSE_QR' is not a value slam_toolbox knows: the "
                          "node uses SPARSE_NORMAL_CHOLESKY",
                          "toolbox.yaml:5: ceres_loss_function: 'SoftL1' is not a value slam_toolbox knows: the node "
                          "uses None"));
  // In a flat file (slamtune's own engine names) an unknown choice stays an error.
  EXPECT_THAT([&] { ApplyParamsYaml(q, "ceres_linear_solver: DENSE_QR\n", "flat.yaml"); },
              ThrowsMessage<InputError>(HasSubstr("ceres_linear_solver = 'DENSE_QR' is out of range")));
}

TEST(ParamsYaml, MinimumTimeIntervalIsTheSynchronousNodesFilter) {
  // Asynchronous node: read, but node-only; Karto's own interval stays 3600.
  MapperParams async = NodeDefaults(RosNode::kSlamToolbox);
  const ParamsYamlReport a =
      ApplyParamsYaml(async, ToolboxYaml({"minimum_time_interval: 1.5", "throttle_scans: 2"}), "a.yaml");
  EXPECT_EQ(async.minimum_time_interval, 3600);
  EXPECT_EQ(async.sync_minimum_time_interval, 1.5);
  EXPECT_EQ(KeyOf(a, "minimum_time_interval").use, KeyUse::kNodeOnly);
  EXPECT_EQ(KeyOf(a, "throttle_scans").use, KeyUse::kNodeOnly);
  // Synchronous node: used by the engine.
  MapperParams sync = NodeDefaults(RosNode::kSlamToolbox);
  sync.node_mode = NodeMode::kSlamToolboxSync;
  const ParamsYamlReport s =
      ApplyParamsYaml(sync, ToolboxYaml({"minimum_time_interval: 1.5", "throttle_scans: 2"}), "s.yaml");
  EXPECT_EQ(sync.sync_minimum_time_interval, 1.5);
  EXPECT_EQ(sync.throttle_scans, 2);
  EXPECT_EQ(KeyOf(s, "minimum_time_interval").use, KeyUse::kEngine);
  EXPECT_EQ(KeyOf(s, "throttle_scans").use, KeyUse::kEngine);
  // Left out, it takes transform_timeout's value, as slam_toolbox_common.cpp declares it.
  MapperParams timeout = sync;
  const ParamsYamlReport t = ApplyParamsYaml(timeout, ToolboxYaml({"transform_timeout: 0.2"}), "t.yaml");
  EXPECT_EQ(timeout.sync_minimum_time_interval, 0.2);
  EXPECT_EQ(KeyOf(t, "transform_timeout").use, KeyUse::kEngine);
  MapperParams both = sync;
  ApplyParamsYaml(both, ToolboxYaml({"transform_timeout: 0.2", "minimum_time_interval: 0.7"}), "b.yaml");
  EXPECT_EQ(both.sync_minimum_time_interval, 0.7);
}

TEST(ParamsYaml, SlamKartosMinimumTimeIntervalIsNotKartos) {
  // slam_karto never stamps its scans: a positive value changes nothing, one <= 0 is not modelled.
  MapperParams p = NodeDefaults(RosNode::kSlamKarto);
  const ParamsYamlReport r = ApplyParamsYaml(p, "minimum_time_interval: 0.5\n", "karto.yaml");
  EXPECT_EQ(p.minimum_time_interval, 3600);
  EXPECT_EQ(KeyOf(r, "minimum_time_interval").use, KeyUse::kNodeOnly);
  const ParamsYamlReport zero = ApplyParamsYaml(p, "minimum_time_interval: 0\n", "karto.yaml");
  EXPECT_EQ(KeyOf(zero, "minimum_time_interval").use, KeyUse::kNotModelled);
  EXPECT_THAT(zero.warnings, ElementsAre(HasSubstr("karto.yaml:1: minimum_time_interval: slam_karto never stamps")));
}

TEST(ParamsYaml, EveryKeyIsClassified) {
  MapperParams p = NodeDefaults(RosNode::kSlamToolbox);
  const ParamsYamlReport r = ApplyParamsYaml(p,
                                             ToolboxYaml({
                                                 "odom_frame: odom",
                                                 "loop_search_maximum_distance: 4.0",
                                                 "mode: localization",
                                                 "map_start_pose: [0.0, 0.0, 0.0]",
                                                 "map_update_interval: 5.0",
                                             }),
                                             "all.yaml");
  ASSERT_EQ(r.keys.size(), 5u);
  EXPECT_EQ(r.keys[0].use, KeyUse::kNodeOnly);
  EXPECT_EQ(r.keys[1].use, KeyUse::kEngine);
  EXPECT_EQ(r.keys[2].use, KeyUse::kNotModelled);
  EXPECT_EQ(r.keys[3].use, KeyUse::kNotModelled);
  EXPECT_EQ(r.keys[4].use, KeyUse::kNodeOnly);
  EXPECT_EQ(r.keys[2].line, 5u);
  EXPECT_EQ(r.warnings.size(), 2u);
  EXPECT_STREQ(NameOf(KeyUse::kEngine), "used by the engine");
  EXPECT_STREQ(NameOf(KeyUse::kNodeOnly), "node-only (no effect on the map)");
  EXPECT_STREQ(NameOf(KeyUse::kNotModelled), "not modelled");
}

}  // namespace
}  // namespace slamtune::slam
