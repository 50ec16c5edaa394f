#include "slamtune/slam/params_yaml.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"

namespace slamtune::slam {
namespace {

using slamtune::testing::ErrorMessageOf;
using ::testing::ElementsAre;
using ::testing::HasSubstr;
using ::testing::Not;
using ::testing::StartsWith;
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

}  // namespace
}  // namespace slamtune::slam
