#include "slamtune/common/key_words.h"

#include <gtest/gtest.h>

#include <cmath>
#include <unordered_map>

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
  EXPECT_EQ(LeastRecentlyUsedHalfCut({7}), 8u);           // the single entry goes
  EXPECT_EQ(LeastRecentlyUsedHalfCut({9, 3}), 9u);        // 3 goes, 9 stays
  EXPECT_EQ(LeastRecentlyUsedHalfCut({5, 1, 4, 2}), 4u);  // 1 and 2 go
}

TEST(KeyWords, EvictLeastRecentlyUsedHalfDropsTheOlderHalfAndItsBytes) {
  struct Value {
    std::uint64_t sequence;
    std::size_t bytes;
  };
  std::unordered_map<int, Value> entries;
  std::size_t bytes = 0;
  for (int k = 0; k < 10; ++k) {
    // Last uses out of insertion order: 9, 19, 7, 17, ..., 1, 11.
    const std::uint64_t use = k % 2 == 0 ? 9 - k : 20 - k;
    entries[k] = {use, static_cast<std::size_t>(k + 1)};
    bytes += k + 1;
  }
  const std::size_t dropped = EvictLeastRecentlyUsedHalf(
      entries, [](const Value& v) { return v.bytes; }, &bytes);
  EXPECT_EQ(dropped, 5u);
  std::size_t left = 0;
  for (const auto& [k, v] : entries) {
    EXPECT_GE(v.sequence, 11u) << k;  // the five most recent uses: 11, 13, 15, 17, 19
    left += v.bytes;
  }
  EXPECT_EQ(bytes, left);
  std::unordered_map<int, Value> empty;
  EXPECT_EQ(EvictLeastRecentlyUsedHalf(
                empty, [](const Value& v) { return v.bytes; }, &bytes),
            0u);
}

}  // namespace
}  // namespace slamtune
