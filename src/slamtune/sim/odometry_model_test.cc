#include "slamtune/sim/odometry_model.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <cmath>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::sim {
namespace {

OdometryNoiseOptions Noiseless() {
  OdometryNoiseOptions options;
  options.translation_noise = 0.0;
  options.rotation_noise_per_m = 0.0;
  options.rotation_noise_per_rad = 0.0;
  options.rotation_scale_bias = 0.0;
  options.heading_drift_per_m = 0.0;
  options.translation_scale_bias = 0.0;
  return options;
}

TEST(OdometryModel, NoiselessOdometryIsExact) {
  OdometryModel odometry(Pose2{1, 2, 0.3}, Noiseless(), 1);
  Pose2 truth{1, 2, 0.3};
  for (int i = 0; i < 200; ++i) {
    const Pose2 delta{0.05, 0.001 * (i % 7), 0.02 * ((i % 5) - 2)};
    truth = Compose(truth, delta);
    odometry.Advance(delta);
  }
  EXPECT_NEAR(odometry.pose().x, truth.x, 1e-9);
  EXPECT_NEAR(odometry.pose().y, truth.y, 1e-9);
  EXPECT_NEAR(odometry.pose().theta, truth.theta, 1e-9);
}

TEST(OdometryModel, SystematicBiasesGiveTheExpectedHeadingDrift) {
  OdometryNoiseOptions options = Noiseless();
  options.rotation_scale_bias = 0.02;
  options.heading_drift_per_m = 0.001;
  OdometryModel odometry(Pose2{}, options, 1);
  // 10 m straight, then a quarter turn in place: drift 0.01 rad + 2% of pi/2.
  for (int i = 0; i < 200; ++i) odometry.Advance(Pose2{0.05, 0, 0});
  for (int i = 0; i < 10; ++i) odometry.Advance(Pose2{0, 0, kPi / 20});
  EXPECT_NEAR(odometry.pose().theta, kPi / 2 * 1.02 + 0.01, 1e-9);
  // The heading drift bends the straight leg: lateral offset of about drift * L^2 / 2 = 0.05 m.
  EXPECT_NEAR(odometry.pose().y, 0.05, 0.002);
}

TEST(OdometryModel, RandomErrorGrowsWithTheSquareRootOfDistance) {
  OdometryNoiseOptions options = Noiseless();
  options.translation_noise = 0.05;  // m/sqrt(m)
  // 400 runs of 4 m in 0.05 m steps and in 0.5 m steps: the distance error's spread is
  // 0.05 * sqrt(4) = 0.1 m in both cases (independent of the step).
  for (double step : {0.05, 0.5}) {
    double sum2 = 0.0;
    for (uint64_t seed = 0; seed < 400; ++seed) {
      OdometryModel odometry(Pose2{}, options, seed);
      for (int i = 0; i < static_cast<int>(std::round(4.0 / step)); ++i) odometry.Advance(Pose2{step, 0, 0});
      sum2 += (odometry.pose().x - 4.0) * (odometry.pose().x - 4.0);
    }
    EXPECT_NEAR(std::sqrt(sum2 / 400), 0.1, 0.012) << "step " << step;
  }
}

TEST(OdometryNoiseOptions, ValidateNamesFieldValueAndRule) {
  OdometryNoiseOptions options;
  EXPECT_NO_THROW(options.Validate());
  options.translation_noise = -1;
  EXPECT_THAT([&] { options.Validate(); }, ::testing::ThrowsMessage<InputError>(::testing::HasSubstr(
                                               "odometry translation_noise = -1: must be finite and >= 0")));
  options = OdometryNoiseOptions();
  options.rotation_scale_bias = 0.7;
  EXPECT_THAT([&] { options.Validate(); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("rotation_scale_bias = 0.7")));
  options = OdometryNoiseOptions();
  options.heading_drift_per_m = 1.0;
  EXPECT_THAT([&] { options.Validate(); },
              ::testing::ThrowsMessage<InputError>(::testing::HasSubstr("heading_drift_per_m = 1")));
}

// A spin fault turns the odometry by its magnitude within its stretch and nowhere else, and
// draws no random numbers: noisy odometry with and without it differs by that turn alone.
TEST(OdometryModel, FaultsAddTheirMotionOnlyInTheirStretch) {
  OdometryNoiseOptions options;
  OdometryFault spin;
  spin.kind = OdometryFaultKind::kSpin;
  spin.start_m = 1.0;
  spin.length_m = 0.1;
  spin.magnitude = 0.5;
  OdometryNoiseOptions faulty = options;
  faulty.faults = {spin};
  OdometryModel a(Pose2{}, options, 7), b(Pose2{}, faulty, 7);
  for (int i = 0; i < 40; ++i) {
    a.Advance(Pose2{0.05, 0, 0});
    b.Advance(Pose2{0.05, 0, 0});
    if (b.travelled_m() < 1.0 - 1e-9) {
      ASSERT_EQ(a.pose(), b.pose()) << "step " << i;  // bit for bit before the fault
    }
  }
  EXPECT_NEAR(b.travelled_m(), 2.0, 1e-12);
  EXPECT_NEAR(NormalizeAngle(b.pose().theta - a.pose().theta), 0.5, 1e-12);
}

}  // namespace
}  // namespace slamtune::sim
