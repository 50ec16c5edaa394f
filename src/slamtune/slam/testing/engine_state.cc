#include "slamtune/slam/testing/engine_state.h"

#include <gtest/gtest.h>

namespace slamtune::slam::testing {

MapperParams FastMapperParams() {
  MapperParams p;
  p.minimum_travel_distance = 0.4;
  p.scan_buffer_size = 20;
  p.loop_match_minimum_chain_size = 5;
  return p;
}

void ExpectSameEngineState(const LogRunner& a, const LogRunner& b, bool same_skips) {
  const Mapper& ma = a.mapper();
  const Mapper& mb = b.mapper();
  ASSERT_EQ(ma.scans().size(), mb.scans().size());
  for (std::size_t k = 0; k < ma.scans().size(); ++k) {
    ASSERT_EQ(ma.scans()[k].corrected_pose(), mb.scans()[k].corrected_pose()) << "scan " << k;
  }
  EXPECT_TRUE(ma.graph() == mb.graph());
  EXPECT_EQ(ma.reference_poses(), mb.reference_poses());
  EXPECT_TRUE(ma.scans_by_laser() == mb.scans_by_laser());
  for (int laser = 0; laser < ma.scans_by_laser().num_lasers(); ++laser) {
    EXPECT_EQ(ma.running_buffer(laser), mb.running_buffer(laser)) << "laser " << laser;
  }
  MapperCounters ca = ma.counters(), cb = mb.counters();
  if (!same_skips) ca.near_chain_matches_skipped = cb.near_chain_matches_skipped = 0;
  EXPECT_EQ(ca, cb);
  ASSERT_EQ(ma.loop_attempts().size(), mb.loop_attempts().size());
  for (std::size_t k = 0; k < ma.loop_attempts().size(); ++k) {
    const LoopAttempt& x = ma.loop_attempts()[k];
    const LoopAttempt& y = mb.loop_attempts()[k];
    EXPECT_EQ(x.scan, y.scan);
    EXPECT_EQ(x.chain_first, y.chain_first);
    EXPECT_EQ(x.coarse_response, y.coarse_response);
    EXPECT_EQ(x.coarse_covariance, y.coarse_covariance);
    EXPECT_EQ(x.fine_response, y.fine_response);
    EXPECT_EQ(x.accepted, y.accepted);
  }
  const auto ta = a.Trajectory(), tb = b.Trajectory();
  ASSERT_EQ(ta.size(), tb.size());
  for (std::size_t k = 0; k < ta.size(); ++k) EXPECT_EQ(ta[k].pose, tb[k].pose) << k;
}

}  // namespace slamtune::slam::testing
