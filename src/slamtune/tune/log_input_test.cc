#include "slamtune/tune/log_input.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"

namespace slamtune::tune {
namespace {

using ::testing::HasSubstr;
using ::testing::ThrowsMessage;

LogInputOptions EveryFieldSet() {
  LogInputOptions o;
  o.lenient = true;
  o.no_return = 30.5;
  o.max_scans = 700;
  o.beams = "per-geometry";
  o.scan_topic = "/scan";
  o.odom_topic = "/odom";
  o.odom_frame = "odom_combined";
  o.base_frame = "base_link";
  o.laser_offset = {0.1, -0.2, 0.3};
  o.max_odom_gap_s = 1.5;
  return o;
}

TEST(LogInputOptions, JsonKeepsEveryField) {
  const LogInputOptions o = EveryFieldSet();
  const LogInputOptions back = LogInputOptions::FromJson(o.ToJson());
  EXPECT_EQ(back.ToJson(), o.ToJson());
  EXPECT_EQ(back.beams, "per-geometry");
  EXPECT_EQ(back.laser_offset, (std::vector<double>{0.1, -0.2, 0.3}));
  EXPECT_NE(LogInputOptions{}.ToJson(), o.ToJson());
}

TEST(LogInputOptions, ReadOptionsCarryTheChoices) {
  const io::LogReadOptions r = EveryFieldSet().ToReadOptions();
  EXPECT_TRUE(r.lenient);
  EXPECT_EQ(r.max_scans, 700u);
  EXPECT_EQ(r.recording.scan_topic, "/scan");
  ASSERT_TRUE(r.recording.laser_offset.has_value());
  EXPECT_DOUBLE_EQ(r.recording.laser_offset->theta, 0.3);
}

TEST(LogInputOptions, ABadBeamPolicyIsNamed) {
  LogInputOptions o;
  o.beams = "strictest";
  EXPECT_THAT([&] { (void)o.ToReadOptions(); }, ThrowsMessage<InputError>(HasSubstr("--beams 'strictest'")));
}

TEST(LogInputOptions, ASliceNeedsALog) {
  LogInputOptions o;
  EXPECT_NO_THROW(o.RequireLogForSlice("office"));
  o.max_scans = 600;
  EXPECT_THAT([&] { o.RequireLogForSlice("office-jump"); },
              ThrowsMessage<InputError>(HasSubstr("--max-scans 600: reads the first scans of a LOG; the built-in "
                                                  "world 'office-jump' is simulated whole")));
}

}  // namespace
}  // namespace slamtune::tune
