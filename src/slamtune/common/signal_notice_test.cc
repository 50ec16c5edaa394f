#include "slamtune/common/signal_notice.h"

#include <gtest/gtest.h>
#include <signal.h>

namespace slamtune {
namespace {

TEST(SignalNoticeDeathTest, SigintPrintsTheLineAndEndsBySigint) {
  EXPECT_EXIT(
      {
        SignalNotice notice("continue with: slamtune optimize --resume out");
        raise(SIGINT);
      },
      ::testing::KilledBySignal(SIGINT),
      "^slamtune: stopped by SIGINT; continue with: slamtune optimize --resume out\n$");
}

TEST(SignalNoticeDeathTest, SigtermPrintsTheLineAndEndsBySigterm) {
  EXPECT_EXIT(
      {
        SignalNotice notice("go on");
        raise(SIGTERM);
      },
      ::testing::KilledBySignal(SIGTERM), "^slamtune: stopped by SIGTERM; go on\n$");
}

TEST(SignalNoticeDeathTest, PreviousHandlersReturnAfterwards) {
  EXPECT_EXIT(
      {
        { SignalNotice notice("not shown"); }
        raise(SIGTERM);
      },
      ::testing::KilledBySignal(SIGTERM), "^$");
}

}  // namespace
}  // namespace slamtune
