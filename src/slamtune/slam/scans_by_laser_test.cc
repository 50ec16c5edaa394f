#include "slamtune/slam/scans_by_laser.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

namespace slamtune::slam {
namespace {

using ::testing::ElementsAre;
using ::testing::IsEmpty;

TEST(ScansByLaser, OneLaserIsTheIdentity) {
  ScansByLaser lasers;
  for (int i = 0; i < 4; ++i) lasers.Add(0);
  EXPECT_EQ(lasers.size(), 4);
  EXPECT_EQ(lasers.num_lasers(), 1);
  EXPECT_THAT(lasers.scans_of(0), ElementsAre(0, 1, 2, 3));
  for (int id = 0; id < 4; ++id) {
    EXPECT_EQ(lasers.laser_of(id), 0);
    EXPECT_EQ(lasers.position(id), id);
  }
}

TEST(ScansByLaser, EachLaserNumbersItsOwnScans) {
  ScansByLaser lasers;
  for (int laser : {0, 2, 0, 0, 2}) lasers.Add(laser);
  EXPECT_EQ(lasers.num_lasers(), 3);
  EXPECT_THAT(lasers.scans_of(0), ElementsAre(0, 2, 3));
  EXPECT_THAT(lasers.scans_of(1), IsEmpty());  // a laser without scans
  EXPECT_THAT(lasers.scans_of(2), ElementsAre(1, 4));
  EXPECT_THAT(lasers.scans_of(7), IsEmpty());
  EXPECT_EQ(lasers.laser_of(4), 2);
  EXPECT_EQ(lasers.position(4), 1);
  EXPECT_EQ(lasers.position(3), 2);
  ScansByLaser copy = lasers;
  EXPECT_TRUE(copy == lasers);
  copy.Add(1);
  EXPECT_FALSE(copy == lasers);
}

}  // namespace
}  // namespace slamtune::slam
