#include "slamtune/slam/params/mapper_params.h"

#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/error_message.h"

namespace slamtune::slam {
namespace {

using slamtune::testing::ErrorMessageOf;
using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(MapperParams, DefaultsAreSlamKartoYaml) {
  const MapperParams p;
  // A few rows of slam_karto's YAML (§9.1), by ROS name.
  const std::pair<const char*, double> yaml[] = {{"loop_search_maximum_distance", 4.0},
                                                 {"loop_match_minimum_chain_size", 10},
                                                 {"loop_match_minimum_response_coarse", 0.8},
                                                 {"loop_match_maximum_variance_coarse", 0.4},
                                                 {"minimum_travel_distance", 0.2},
                                                 {"scan_buffer_size", 70},
                                                 {"link_scan_maximum_distance", 10.0},
                                                 {"resolution", 0.05},
                                                 {"min_pass_through", 2},
                                                 {"occupancy_threshold", 0.1}};
  for (const auto& [name, value] : yaml) EXPECT_EQ(GetNumeric(p, name), value) << name;
  EXPECT_DOUBLE_EQ(p.LoopMatchMaximumVarianceCoarseInternal(), 0.16);
  EXPECT_DOUBLE_EQ(p.DistanceVariancePenaltyInternal(), 0.09);
  EXPECT_NEAR(p.AngleVariancePenaltyInternal(), 0.121801, 1e-9);
  EXPECT_EQ(p.solver, SolverKind::kSpa);
  EXPECT_NO_THROW(p.Validate());
}

TEST(MapperParams, SlamToolboxPresetUsesItsYaml) {
  const MapperParams p = MapperParams::Preset("slam_toolbox");
  EXPECT_EQ(p.loop_search_maximum_distance, 3.0);
  EXPECT_EQ(p.loop_match_minimum_response_coarse, 0.35);
  EXPECT_DOUBLE_EQ(p.LoopMatchMaximumVarianceCoarseInternal(), 9.0);
  EXPECT_EQ(p.link_scan_maximum_distance, 1.5);
  EXPECT_EQ(p.scan_buffer_size, 10);
  EXPECT_TRUE(p.use_response_expansion);
  EXPECT_EQ(p.solver, SolverKind::kCeres);
  EXPECT_EQ(p.minimum_time_interval, 3600);  // not passed to the toolbox Mapper (§3.4)
  EXPECT_NO_THROW(p.Validate());
  EXPECT_NE(p, MapperParams{});
  EXPECT_THAT([] { MapperParams::Preset("cartographer"); },
              ThrowsMessage<InputError>(HasSubstr("unknown preset 'cartographer'")));
}

TEST(MapperParams, RangeThresholdRules) {
  MapperParams p;
  EXPECT_EQ(p.RangeThreshold(0.0, 80.0), 12.0);
  EXPECT_EQ(p.RangeThreshold(0.0, 8.0), 8.0);
  EXPECT_EQ(p.RangeThreshold(15.0, 80.0), 15.0);
  p.range_threshold_rule = RangeThresholdRule::kSlamToolbox;
  p.max_laser_range = 20.0;
  EXPECT_EQ(p.RangeThreshold(0.0, 80.0), 20.0);
  EXPECT_EQ(p.RangeThreshold(0.0, 15.0), 15.0);
  p.max_laser_range = 0.0;
  EXPECT_EQ(p.RangeThreshold(0.0, 50.0), 50.0);
}

TEST(MapperParams, MatcherOptionsUseInternalUnits) {
  const MapperParams p;
  const ScanMatcherOptions seq = p.SequentialMatcherOptions(12.0);
  EXPECT_EQ(seq.search_dimension, 0.3);
  EXPECT_EQ(seq.search_resolution, 0.01);
  EXPECT_DOUBLE_EQ(seq.distance_variance_penalty, 0.09);
  EXPECT_EQ(seq.fine_angle_step, 0.00349);
  EXPECT_EQ(seq.range_threshold, 12.0);
  const ScanMatcherOptions loop = p.LoopMatcherOptions(12.0);
  EXPECT_EQ(loop.search_dimension, 8.0);
  EXPECT_EQ(loop.search_resolution, 0.05);
  EXPECT_EQ(loop.smear_deviation, 0.03);
}

TEST(MapperParams, GridOptionsTakeTheMapParameters) {
  MapperParams p;
  p.resolution = 0.1;
  p.min_pass_through = 5;
  p.occupancy_threshold = 0.25;
  const OccupancyGridOptions grid = GridOptionsOf(p);
  EXPECT_EQ(grid.resolution, 0.1);
  EXPECT_EQ(grid.min_pass_through, 5);
  EXPECT_EQ(grid.occupancy_threshold, 0.25);
  EXPECT_EQ(grid.max_cells, OccupancyGridOptions{}.max_cells);
  // The defaults of both agree: slam_karto's map parameters.
  const OccupancyGridOptions defaults = GridOptionsOf(MapperParams{});
  EXPECT_EQ(defaults.resolution, OccupancyGridOptions{}.resolution);
  EXPECT_EQ(defaults.min_pass_through, OccupancyGridOptions{}.min_pass_through);
  EXPECT_EQ(defaults.occupancy_threshold, OccupancyGridOptions{}.occupancy_threshold);
}

TEST(MapperParams, ValidationNamesParameterValueAndRule) {
  MapperParams p;
  p.loop_match_minimum_chain_size = 0;
  EXPECT_THAT([&] { p.Validate(); },
              ThrowsMessage<InputError>(
                  HasSubstr("loop_match_minimum_chain_size = 0 is out of range: must be an integer >= 1")));
  p = {};
  p.loop_search_maximum_distance = -1.5;
  EXPECT_THAT([&] { p.Validate(); },
              ThrowsMessage<InputError>(HasSubstr("loop_search_maximum_distance = -1.5 is out of range")));
  p = {};
  p.loop_match_minimum_response_coarse = 1.2;
  EXPECT_THAT([&] { p.Validate(); },
              ThrowsMessage<InputError>(
                  HasSubstr("loop_match_minimum_response_coarse = 1.2 is out of range: must be in [0, 1]")));
  p = {};
  p.correlation_search_space_dimension = 0.31;
  EXPECT_THAT([&] { p.Validate(); }, ThrowsMessage<InputError>(HasSubstr("must be an even integer")));
  p = {};
  p.loop_search_space_dimension = 8.05;  // 161 cells: odd
  EXPECT_THAT([&] { p.Validate(); }, ThrowsMessage<InputError>(HasSubstr("loop_search_space_dimension = 8.05")));
  p = {};
  p.correlation_search_space_smear_deviation = 0.2;  // > 10 rho
  EXPECT_THAT([&] { p.Validate(); },
              ThrowsMessage<InputError>(HasSubstr("correlation_search_space_smear_deviation = 0.2")));
  p = {};
  EXPECT_THAT([&] { SetFromString(p, "solver", "g2o"); },
              ThrowsMessage<InputError>(HasSubstr("solver = 'g2o' is out of range: must be spa or ceres")));
  EXPECT_THAT(
      [&] {
        p.Validate({{"ceres_loss_function", "SoftL1"}});
      },
      ThrowsMessage<InputError>(
          HasSubstr("ceres_loss_function = 'SoftL1' is out of range: must be None, HuberLoss or CauchyLoss")));
  p = {};
  p.minimum_travel_distance = std::nan("");
  EXPECT_THAT([&] { p.Validate(); }, ThrowsMessage<InputError>(HasSubstr("minimum_travel_distance = nan")));
}

TEST(MapperParams, NumericAccessByRosName) {
  MapperParams p;
  EXPECT_EQ(GetNumeric(p, "loop_match_minimum_chain_size"), 10.0);
  EXPECT_EQ(GetNumeric(p, "do_loop_closing"), 1.0);
  SetNumeric(p, "loop_match_minimum_chain_size", 4);
  EXPECT_EQ(p.loop_match_minimum_chain_size, 4);
  SetNumeric(p, "loop_search_maximum_distance", 6.5);
  EXPECT_EQ(p.loop_search_maximum_distance, 6.5);
  SetNumeric(p, "do_loop_closing", 0);
  EXPECT_FALSE(p.do_loop_closing);

  const MapperParams before = p;
  EXPECT_THAT([&] { SetNumeric(p, "loop_match_minimum_chain_size", 2.5); },
              ThrowsMessage<InputError>(HasSubstr("loop_match_minimum_chain_size = 2.5 is out of range")));
  EXPECT_THAT([&] { SetNumeric(p, "loop_match_minimum_chain_size", 0); },
              ThrowsMessage<InputError>(HasSubstr("must be an integer >= 1")));
  EXPECT_THAT([&] { SetNumeric(p, "use_scan_barycenter", 0.5); },
              ThrowsMessage<InputError>(HasSubstr("true or false")));
  EXPECT_THAT([&] { SetNumeric(p, "solver", 1); }, ThrowsMessage<InputError>(HasSubstr("is a string")));
  EXPECT_THAT([&] { SetNumeric(p, "loop_radius", 1); },
              ThrowsMessage<InputError>(HasSubstr("unknown mapper parameter 'loop_radius'")));
  EXPECT_EQ(p, before);  // validated before changing state
}

TEST(MapperParams, OverridesFromText) {
  MapperParams p;
  ApplyOverride(p, "loop_match_minimum_response_coarse=0.55");
  ApplyOverride(p, " use_response_expansion = true ");
  ApplyOverride(p, "solver=ceres");
  EXPECT_EQ(p.loop_match_minimum_response_coarse, 0.55);
  EXPECT_TRUE(p.use_response_expansion);
  EXPECT_EQ(p.solver, SolverKind::kCeres);
  EXPECT_THAT([&] { ApplyOverride(p, "scan_buffer_size"); }, ThrowsMessage<InputError>(HasSubstr("form name=value")));
  EXPECT_THAT([&] { ApplyOverride(p, "scan_buffer_size=ten"); },
              ThrowsMessage<InputError>(HasSubstr("scan_buffer_size = 'ten' is not a number (int expected")));
  EXPECT_THAT([&] { ApplyOverride(p, "use_response_expansion=maybe"); }, ThrowsMessage<InputError>(HasSubstr("maybe")));
}

// A consistent set is taken whatever the order it is given in: the values are validated
// together, after the last (one at a time, the first would be checked against the old others).
TEST(MapperParams, ConsistentSetsAreValidatedTogether) {
  const std::vector<std::string> sets = {"correlation_search_space_dimension=0.6",
                                         "correlation_search_space_resolution=0.1",
                                         "correlation_search_space_smear_deviation=0.2"};
  MapperParams one_by_one;
  ApplyOverride(one_by_one, sets[0]);
  EXPECT_THROW(ApplyOverride(one_by_one, sets[1]), InputError) << "the old smear 0.03 is below 0.5 x 0.1";
  MapperParams p;
  ApplyOverrides(p, sets);
  EXPECT_EQ(p.correlation_search_space_dimension, 0.6);
  EXPECT_EQ(p.correlation_search_space_resolution, 0.1);
  EXPECT_EQ(p.correlation_search_space_smear_deviation, 0.2);
  MapperParams q;
  SetNumerics(q, {{"correlation_search_space_smear_deviation", 0.2},
                  {"correlation_search_space_resolution", 0.1},
                  {"correlation_search_space_dimension", 0.6}});
  EXPECT_EQ(q, p);
  // An inconsistent set is still refused, and nothing is changed.
  MapperParams r;
  EXPECT_THROW(ApplyOverrides(r, {"correlation_search_space_resolution=0.1"}), InputError);
  EXPECT_EQ(r, MapperParams{});
}

// An override that breaks a rule with a value the user did not give says which value is the
// base's; a consistent set names nothing; overrides alone in conflict name only themselves.
TEST(MapperParams, AnOverrideInConflictWithABaseValueSaysWhichIsTheBases) {
  MapperParams p;
  ApplyOverrides(p, {"correlation_search_space_dimension=2", "correlation_search_space_resolution=1.0",
                     "correlation_search_space_smear_deviation=1.0"});
  EXPECT_EQ(p.correlation_search_space_smear_deviation, 1.0);
  MapperParams q;
  EXPECT_EQ(ErrorMessageOf([&] {
              ApplyOverrides(q, {"correlation_search_space_dimension=2", "correlation_search_space_resolution=1.0"});
            }),
            "mapper parameters correlation_search_space_resolution = 1 and correlation_search_space_smear_deviation "
            "= 0.03 are inconsistent: the smear deviation must be in [0.5, 10] x the resolution = [0.5, 10] "
            "(correlation_search_space_smear_deviation is not given with --set: the base configuration's value; set "
            "it too, or choose values that fit it)");
  EXPECT_EQ(ErrorMessageOf([&] {
              ApplyOverrides(q, {"correlation_search_space_dimension=2.5", "correlation_search_space_resolution=1.0",
                                 "correlation_search_space_smear_deviation=1.0"});
            }),
            "mapper parameters correlation_search_space_dimension = 2.5 and correlation_search_space_resolution = 1 "
            "are inconsistent: dimension / resolution = 2.5 must be an even integer");
  EXPECT_EQ(q, MapperParams{});
}

TEST(MapperParams, UnknownNamesGetTheClosestKnownOne) {
  MapperParams p;
  EXPECT_THAT([&] { ApplyOverride(p, "loop_search_maximum_distanse=3"); },
              ThrowsMessage<InputError>(HasSubstr("(did you mean 'loop_search_maximum_distance'?)")));
  EXPECT_THAT(ErrorMessageOf([&] { ApplyOverride(p, "frobnicate=3"); }), ::testing::Not(HasSubstr("did you mean")));
}

TEST(MapperParams, NamedValuesCoverTheTableAndRoundTrip) {
  const MapperParams source = MapperParams::Preset("slam_toolbox");
  const auto values = ToNamedValues(source);
  ASSERT_EQ(values.size(), ParamTable().size());
  MapperParams rebuilt;
  for (const NamedParam& v : values) {
    const std::string text = std::visit(
        [](const auto& x) -> std::string {
          using T = std::decay_t<decltype(x)>;
          if constexpr (std::is_same_v<T, std::string>)
            return x;
          else if constexpr (std::is_same_v<T, bool>)
            return x ? "true" : "false";
          else
            return fmt::format("{}", x);
        },
        v.value);
    SetFromString(rebuilt, v.name, text);
  }
  EXPECT_EQ(rebuilt, source);
  for (const ParamInfo& info : ParamTable()) EXPECT_EQ(FindParam(info.name), &info);
  EXPECT_EQ(FindParam("nope"), nullptr);
}

TEST(MapperParams, CeresCombinationThatAbortsCeresIsRefused) {
  MapperParams p = MapperParams::Preset("slam_toolbox");
  p.ceres_linear_solver = CeresLinearSolver::kCgnr;
  p.ceres_preconditioner = CeresPreconditioner::kSchurJacobi;
  EXPECT_THROW(p.Validate(), InputError);
  p.ceres_preconditioner = CeresPreconditioner::kJacobi;
  EXPECT_NO_THROW(p.Validate());
  p.ceres_preconditioner = CeresPreconditioner::kSchurJacobi;
  p.solver = SolverKind::kSpa;  // the SPA back-end reads none of them
  EXPECT_NO_THROW(p.Validate());
}

TEST(MapperParams, NodeModesAndPresets) {
  EXPECT_EQ(MapperParams::Preset("slam_karto").node_mode, NodeMode::kSlamKarto);
  EXPECT_EQ(MapperParams::Preset("open_karto").node_mode, NodeMode::kSlamKarto);
  EXPECT_EQ(MapperParams::Preset("slam_toolbox").node_mode, NodeMode::kSlamToolboxAsync);
  MapperParams sync = MapperParams::Preset("slam_toolbox_sync");
  EXPECT_EQ(sync.node_mode, NodeMode::kSlamToolboxSync);
  EXPECT_TRUE(IsSynchronous(sync.node_mode));
  sync.node_mode = NodeMode::kSlamToolboxAsync;
  EXPECT_EQ(sync, MapperParams::Preset("slam_toolbox"));  // the shipped files' mapper values are the same
  MapperParams offline = MapperParams::Preset("slam_toolbox_offline");
  EXPECT_TRUE(IsSynchronous(offline.node_mode));
  offline.node_mode = NodeMode::kSlamToolboxAsync;
  EXPECT_EQ(offline, MapperParams::Preset("slam_toolbox"));
  for (const std::string& name : PresetNames()) EXPECT_NO_THROW(MapperParams::Preset(name).Validate()) << name;
  EXPECT_EQ(PresetList(), "slam_karto, open_karto, slam_toolbox, slam_toolbox_sync or slam_toolbox_offline");
  MapperParams p;
  SetFromString(p, "node_mode", "slam_toolbox_offline");
  EXPECT_EQ(p.node_mode, NodeMode::kSlamToolboxOffline);
  EXPECT_THROW(SetFromString(p, "node_mode", "slam_toolbox_fast"), InputError);
}

}  // namespace
}  // namespace slamtune::slam
