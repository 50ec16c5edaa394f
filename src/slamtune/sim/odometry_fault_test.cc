#include "slamtune/sim/odometry_fault.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::sim {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

TEST(OdometryFault, KindNamesRoundTrip) {
  for (OdometryFaultKind kind : {OdometryFaultKind::kSpin, OdometryFaultKind::kJump, OdometryFaultKind::kReverse}) {
    EXPECT_EQ(ParseOdometryFaultKind(OdometryFaultKindName(kind)), kind);
  }
  EXPECT_FALSE(ParseOdometryFaultKind("slip").has_value());
}

TEST(OdometryFault, StepsOutsideTheStretchAreUntouched) {
  const std::vector<OdometryFault> faults = {OdometryFault{OdometryFaultKind::kSpin, 10.0, 1.0, 0.5}};
  EXPECT_FALSE(FaultEffectOnStep(faults, 9.95, 0.05).active);  // ends where the fault starts
  EXPECT_FALSE(FaultEffectOnStep(faults, 11.0, 0.05).active);  // starts where it ends
  EXPECT_FALSE(FaultEffectOnStep(faults, 10.5, 0.0).active);   // no motion
  EXPECT_FALSE(FaultEffectOnStep({}, 10.5, 0.05).active);
}

TEST(OdometryFault, EachKindAddsItsShareOfTheStretch) {
  const double half = 0.5;
  const FaultEffect spin = FaultEffectOnStep({OdometryFault{OdometryFaultKind::kSpin, 10.0, 1.0, 0.6}}, 9.75, half);
  EXPECT_TRUE(spin.active);
  EXPECT_NEAR(spin.extra_rotation, 0.6 * 0.25, 1e-12);  // a quarter of the stretch lies in the step
  EXPECT_EQ(spin.extra_distance, 0.0);
  const FaultEffect jump = FaultEffectOnStep({OdometryFault{OdometryFaultKind::kJump, 10.0, 0.2, 0.5}}, 9.9, half);
  EXPECT_NEAR(jump.extra_distance, 0.5, 1e-12);  // the whole stretch lies in the step
  EXPECT_EQ(jump.extra_rotation, 0.0);
  const FaultEffect reverse =
      FaultEffectOnStep({OdometryFault{OdometryFaultKind::kReverse, 10.0, 2.0, 0.0}}, 10.2, half);
  EXPECT_NEAR(reverse.extra_distance, -2.0 * half, 1e-12);  // reported = true - 2 true = -true
}

TEST(OdometryFault, OverlappingFaultsAdd) {
  const std::vector<OdometryFault> faults = {OdometryFault{OdometryFaultKind::kSpin, 0.0, 1.0, 0.2},
                                             OdometryFault{OdometryFaultKind::kSpin, 0.5, 1.0, 0.4}};
  EXPECT_NEAR(FaultEffectOnStep(faults, 0.5, 0.5).extra_rotation, 0.1 + 0.2, 1e-12);
}

TEST(OdometryFault, SummedOverStepsTheWholeMagnitudeIsReported) {
  const std::vector<OdometryFault> faults = {OdometryFault{OdometryFaultKind::kJump, 3.01, 0.37, 0.8},
                                             OdometryFault{OdometryFaultKind::kSpin, 3.2, 0.3, DegToRad(30)}};
  double distance = 0.0, rotation = 0.0;
  for (int i = 0; i < 200; ++i) {
    const FaultEffect e = FaultEffectOnStep(faults, 0.03 * i, 0.03);
    distance += e.extra_distance;
    rotation += e.extra_rotation;
  }
  EXPECT_NEAR(distance, 0.8, 1e-12);
  EXPECT_NEAR(rotation, DegToRad(30), 1e-12);
}

TEST(OdometryFault, ValidateNamesFieldValueAndRule) {
  EXPECT_NO_THROW((OdometryFault{OdometryFaultKind::kSpin, 1.0, 0.1, 0.5}).Validate("faults[2]"));
  EXPECT_THAT(
      [] {
        (OdometryFault{OdometryFaultKind::kSpin, -1.0, 0.1, 0.5}).Validate("faults[2]");
      },
      ThrowsMessage<InputError>(HasSubstr("faults[2] (spin) start_m = -1: must be")));
  EXPECT_THAT(
      [] {
        (OdometryFault{OdometryFaultKind::kJump, 1.0, 0.0, 0.5}).Validate("faults[2]");
      },
      ThrowsMessage<InputError>(HasSubstr("faults[2] (jump) length_m = 0: must be")));
  EXPECT_THAT(
      [] {
        (OdometryFault{OdometryFaultKind::kJump, 1.0, 0.1, 11.0}).Validate("faults[2]");
      },
      ThrowsMessage<InputError>(HasSubstr("magnitude = 11: must be in [-10, 10] m")));
  EXPECT_THAT(
      [] {
        (OdometryFault{OdometryFaultKind::kSpin, 1.0, 0.1, 7.0}).Validate("faults[2]");
      },
      ThrowsMessage<InputError>(HasSubstr("(spin) magnitude = 7")));
  EXPECT_THAT(
      [] {
        (OdometryFault{OdometryFaultKind::kReverse, 1.0, 0.1, 0.5}).Validate("faults[2]");
      },
      ThrowsMessage<InputError>(HasSubstr("(reverse) magnitude = 0.5: must be 0")));
}

TEST(OdometryFault, ParsesTheCommandLineForm) {
  const OdometryFault spin = ParseOdometryFault("spin,40,0.1,30");
  EXPECT_EQ(spin.kind, OdometryFaultKind::kSpin);
  EXPECT_EQ(spin.start_m, 40.0);
  EXPECT_EQ(spin.length_m, 0.1);
  EXPECT_NEAR(spin.magnitude, DegToRad(30), 1e-15);  // degrees on the command line
  const OdometryFault jump = ParseOdometryFault("jump,12.5,0.3,-0.6");
  EXPECT_EQ(jump.kind, OdometryFaultKind::kJump);
  EXPECT_EQ(jump.magnitude, -0.6);
  const OdometryFault reverse = ParseOdometryFault("reverse,7,1.5");
  EXPECT_EQ(reverse.kind, OdometryFaultKind::kReverse);
  EXPECT_EQ(reverse.length_m, 1.5);
  EXPECT_EQ(reverse.magnitude, 0.0);
  EXPECT_THROW(ParseOdometryFault("slip,1,1,1"), InputError);
  EXPECT_THROW(ParseOdometryFault("reverse,1,1,1"), InputError);
  EXPECT_THROW(ParseOdometryFault("jump,1,1"), InputError);
  EXPECT_THROW(ParseOdometryFault("jump,1,x,1"), InputError);
  EXPECT_THROW(ParseOdometryFault("jump,1,0,1"), InputError);  // validated
  try {
    ParseOdometryFault("spin,1,1");
    FAIL() << "no exception";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("--fault 'spin,1,1': spin takes 4 fields, got 3"));
  }
}

TEST(OdometryFault, DescribeSaysWhatWasReported) {
  EXPECT_EQ(ParseOdometryFault("spin,40,0.1,30").Describe(), "spin at 40 m over 0.1 m: 30 deg reported, not turned");
  EXPECT_EQ(ParseOdometryFault("jump,12,0.3,0.6").Describe(), "jump at 12 m over 0.3 m: 0.6 m reported, not travelled");
  EXPECT_EQ(ParseOdometryFault("reverse,7,1.5").Describe(), "reverse at 7 m over 1.5 m: travel reported backwards");
}

}  // namespace
}  // namespace slamtune::sim
