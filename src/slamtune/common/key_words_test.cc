#include "slamtune/common/key_words.h"

#include <gtest/gtest.h>

#include <cmath>

namespace slamtune {
namespace {

TEST(KeyWords, BitsTellApartWhatCompareEqual) {
  EXPECT_NE(KeyBits(0.0), KeyBits(-0.0));  // equal as doubles, different results possible
  EXPECT_NE(KeyBits(1.0), KeyBits(std::nextafter(1.0, 2.0)));
  EXPECT_EQ(KeyInt(-1), ~std::uint64_t{0});
}

TEST(KeyWords, StringsAreLengthPrefixed) {
  std::vector<std::uint64_t> a, b;
  AppendKeyString("ab", &a);
  AppendKeyString("c", &a);
  AppendKeyString("a", &b);
  AppendKeyString("bc", &b);
  EXPECT_NE(a, b);
}

TEST(KeyWords, PoseAppendsThreeWordsAndHashFollowsEquality) {
  std::vector<std::uint64_t> a, b;
  AppendKeyPose({1.0, 2.0, 0.5}, &a);
  AppendKeyPose({1.0, 2.0, 0.5}, &b);
  ASSERT_EQ(a.size(), 3u);
  EXPECT_EQ(a, b);
  EXPECT_EQ(KeyWordsHash{}(a), KeyWordsHash{}(b));
  b[2] ^= 1;
  EXPECT_NE(KeyWordsHash{}(a), KeyWordsHash{}(b));  // not guaranteed in general; true for this mix
}

TEST(KeyWords, HashOfAnArrayEqualsHashOfTheSameWordsInAVector) {
  const std::array<std::uint64_t, 3> a = {1, 2, 3};
  const std::vector<std::uint64_t> v = {1, 2, 3};
  EXPECT_EQ(KeyWordsHash{}(a), KeyWordsHash{}(v));
}

TEST(KeyWords, LeastRecentlyUsedHalfCutDropsTheOlderHalfAndAtLeastOne) {
  EXPECT_EQ(LeastRecentlyUsedHalfCut({}), 0u);
  EXPECT_EQ(LeastRecentlyUsedHalfCut({7}), 8u);      // the single entry goes
  EXPECT_EQ(LeastRecentlyUsedHalfCut({9, 3}), 9u);   // 3 goes, 9 stays
  EXPECT_EQ(LeastRecentlyUsedHalfCut({5, 1, 4, 2}), 4u);  // 1 and 2 go
}

}  // namespace
}  // namespace slamtune
