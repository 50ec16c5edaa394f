#include "slamtune/slam/matching/back_face_filter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

namespace slamtune::slam {
namespace {

using Points = std::vector<Eigen::Vector2d>;

// Hand-made outline seen from the origin (§4.3): 0-3 turn counter-clockwise (front side),
// 4 jumps back clockwise (so the stretch ending at 3 is seen from behind), 5-6 go on
// counter-clockwise. 2 is within 10 cm of the anchor 1 and neither opens nor closes a stretch.
Points Outline(const Eigen::Vector2d& shift) {
  Points p = {{2, 0}, {2, 0.5}, {2, 0.55}, {2, 1.0}, {2, 0.2}, {2, 0.7}, {2, 1.2}};
  for (auto& q : p) q += shift;
  return p;
}

TEST(BackFaceFilter, DropsBackFacingStretchAndLastSegment) {
  const Points p = Outline({0, 0});
  const Points valid = FilterBackFaces(p, {0, 0});
  // Kept: 0 (closed by 1), 1-2 (closed by 3), 4 (closed by 5), 5 (closed by 6).
  // Dropped: 3 (next anchor 4 is on the wrong side), 6 (after the last anchor).
  const Points expected = {p[0], p[1], p[2], p[4], p[5]};
  EXPECT_EQ(valid, expected);
}

TEST(BackFaceFilter, DependsOnlyOnPositionsRelativeToTheViewpoint) {
  const Eigen::Vector2d shift(3.0, -1.0);
  const Points p = Outline(shift);
  const Points expected = {p[0], p[1], p[2], p[4], p[5]};
  EXPECT_EQ(FilterBackFaces(p, shift), expected);
}

TEST(BackFaceFilter, ViewpointOnTheOtherSideFlipsTheVerdict) {
  // Seen from (4, 0), beyond the wall x = 2, the turning sense reverses.
  const Points p = Outline({0, 0});
  const Points valid = FilterBackFaces(p, {4, 0});
  const Points expected = {p[3]};  // only the stretch closed by the clockwise jump 3 -> 4
  EXPECT_EQ(valid, expected);
}

TEST(BackFaceFilter, LeadingNaNIsOutputButNeverAnAnchor) {
  const double nan = std::nan("");
  const Points p = {{nan, nan}, {2, 0}, {2, 0.5}, {2, 1.0}};
  const Points valid = FilterBackFaces(p, {0, 0});
  // The anchor starts at the first non-NaN point (1); the pending stretch still starts at 0,
  // so the NaN point is output (the grid insertion drops it).
  ASSERT_EQ(valid.size(), 3u);
  EXPECT_TRUE(std::isnan(valid[0].x()));
  EXPECT_EQ(valid[1], p[1]);
  EXPECT_EQ(valid[2], p[2]);
}

TEST(BackFaceFilter, NaNInsideNeitherOpensNorClosesAStretch) {
  const double nan = std::nan("");
  const Points p = {{2, 0}, {2, 0.5}, {nan, nan}, {2, 1.0}, {2, 1.5}};
  const Points valid = FilterBackFaces(p, {0, 0});
  ASSERT_EQ(valid.size(), 4u);
  EXPECT_EQ(valid[0], p[0]);
  EXPECT_EQ(valid[1], p[1]);
  EXPECT_TRUE(std::isnan(valid[2].x()));
  EXPECT_EQ(valid[3], p[3]);
}

TEST(BackFaceFilter, InfinitePointCanBeTheAnchor) {
  // An inf reading at 45 degrees gives (inf, inf): not NaN, so it is the first anchor; the
  // side test against it is NaN, which counts as "keep" (§4.3 [QUIRK]).
  const double inf = std::numeric_limits<double>::infinity();
  const Points p = {{inf, inf}, {2, 0}, {2, 0.5}};
  const Points valid = FilterBackFaces(p, {0, 0});
  ASSERT_EQ(valid.size(), 2u);
  EXPECT_TRUE(std::isinf(valid[0].x()));
  EXPECT_EQ(valid[1], p[1]);
}

TEST(BackFaceFilter, EmptyAndSinglePointScansGiveNothing) {
  EXPECT_TRUE(FilterBackFaces(Points{}, {0, 0}).empty());
  EXPECT_TRUE(FilterBackFaces(Points{{1, 1}}, {0, 0}).empty());
}

}  // namespace
}  // namespace slamtune::slam
