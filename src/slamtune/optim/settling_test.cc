#include "slamtune/optim/settling.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include "slamtune/common/error.h"

namespace slamtune::optim {
namespace {

using ::testing::HasSubstr;

SearchSpace OneDimension() {
  SearchSpace s;
  s.dimensions = {{"loop_search_maximum_distance", 2.0, 6.0, false}};
  return s;
}

using Vectors = std::vector<std::vector<double>>;

TEST(FrontMovement, IsZeroForTheSameFrontAndScaleFree) {
  const Vectors front = {{0.0, 1.0}, {0.5, 0.5}, {1.0, 0.0}};
  EXPECT_DOUBLE_EQ(FrontMovement(front, front), 0.0);
  EXPECT_DOUBLE_EQ(FrontMovement({}, front), 1.0);
  // Every point moved by a tenth of the range in the first objective.
  const Vectors moved = {{0.1, 1.0}, {0.6, 0.5}, {1.1, 0.0}};
  EXPECT_NEAR(FrontMovement(front, moved), 0.1, 1e-12);
  Vectors scaled = front, scaled_moved = moved;
  for (auto* v : {&scaled, &scaled_moved})
    for (auto& p : *v) p[0] *= 1000.0;
  EXPECT_NEAR(FrontMovement(scaled, scaled_moved), 0.1, 1e-12);
}

TEST(NonDominatedVectors, KeepsTheFrontOnce) {
  EXPECT_EQ(NonDominatedVectors({{1, 2}, {2, 1}, {2, 2}, {1, 2}}), (Vectors{{1, 2}, {2, 1}}));
}

TEST(SettlingRule, SettlesAfterTheWindowOfCalmGenerations) {
  SettlingRule rule({true, 0.0025, 3}, OneDimension());
  const Vectors x = {{3.0}, {3.0}, {4.0}};
  const Vectors f = {{1.0, 2.0}, {1.0, 2.0}, {2.0, 1.0}};
  EXPECT_FALSE(rule.Update(1, x, f));  // nothing to compare with
  EXPECT_FALSE(rule.Update(2, x, f));
  EXPECT_FALSE(rule.Update(3, x, f));
  EXPECT_TRUE(rule.Update(4, x, f));
  EXPECT_EQ(rule.settled_at(), 4u);
  EXPECT_TRUE(rule.Update(5, x, f));  // stays settled
  EXPECT_EQ(rule.settled_at(), 4u);
  EXPECT_THAT(rule.Describe(60), HasSubstr("stopped after generation 4 of 60"));
}

TEST(SettlingRule, AMovingFrontOrAChangingAnswerKeepsItGoing) {
  SettlingRule moving({true, 0.0025, 2}, OneDimension());
  for (unsigned g = 1; g <= 10; ++g) {
    const double shift = 0.5 / g;  // still moving by more than the tolerance
    EXPECT_FALSE(moving.Update(g, {{3.0}, {4.0}}, {{1.0 + shift, 2.0}, {2.0, 1.0 - shift}})) << g;
  }
  EXPECT_THAT(moving.Describe(10),
              HasSubstr("ran all 10 generations: the answer was still changing (the front still moved"));
  // The same front, but the map most individuals share alternates between its two ends.
  SettlingRule flipping({true, 0.0025, 2}, OneDimension());
  for (unsigned g = 1; g <= 10; ++g) {
    if (g % 2) {
      EXPECT_FALSE(flipping.Update(g, {{3.0}, {3.0}, {4.0}}, {{1.0, 2.0}, {1.0, 2.0}, {2.0, 1.0}})) << g;
    } else {
      EXPECT_FALSE(flipping.Update(g, {{3.0}, {4.0}, {4.0}}, {{1.0, 2.0}, {2.0, 1.0}, {2.0, 1.0}})) << g;
    }
  }
  EXPECT_THAT(flipping.Describe(10),
              HasSubstr("below the tolerance 0.0025, but the recommended or the knee map changed"));
}

TEST(SettlingRule, SetsThatGiveTheSameMapAreOneAnswer) {
  // The majority alternates between r 3 and r 5, which give the same map: settled.
  SettlingRule same_map({true, 0.0025, 2}, OneDimension());
  bool settled = false;
  for (unsigned g = 1; g <= 4 && !settled; ++g) {
    const double r = g % 2 ? 3.0 : 5.0;
    settled = same_map.Update(g, {{r}, {r}, {4.0}}, {{1.0, 2.0}, {1.0, 2.0}, {2.0, 1.0}});
  }
  EXPECT_TRUE(settled);
  EXPECT_EQ(same_map.settled_at(), 3u);
}

TEST(SettlingRule, WithoutASharedSetTheRecommendationIsTheLowestNormalisedSum) {
  // Every individual differs and the population order changes each generation; the front and
  // its lowest-sum member do not: settled (a "first individual" rule would flip forever).
  SettlingRule spread({true, 0.0025, 2}, OneDimension());
  const Vectors fa = {{0.0, 1.0}, {0.4, 0.4}, {1.0, 0.0}};
  const Vectors fb = {{1.0, 0.0}, {0.0, 1.0}, {0.4, 0.4}};
  EXPECT_FALSE(spread.Update(1, {{2.0}, {3.0}, {4.0}}, fa));
  EXPECT_FALSE(spread.Update(2, {{4.0}, {2.0}, {3.0}}, fb));
  EXPECT_TRUE(spread.Update(3, {{2.0}, {3.0}, {4.0}}, fa));
}

TEST(SettlingRule, DisabledNeverStopsAndBadOptionsAreRefused) {
  SettlingRule off({false, 0.0025, 1}, OneDimension());
  for (unsigned g = 1; g <= 5; ++g) EXPECT_FALSE(off.Update(g, {{3.0}}, {{1.0, 1.0}}));
  EXPECT_EQ(off.Describe(5), "ran the fixed budget of 5 generations");
  EXPECT_THROW(SettlingRule({true, 0.0, 3}, OneDimension()), InputError);
  EXPECT_THROW(SettlingRule({true, 0.01, 0}, OneDimension()), InputError);
}

// The sound-answer rule (a broken map's search): the failed score is {9, 9}.
SettlingOptions SoundAnswer(int window) {
  SettlingOptions o;
  o.sound_answer_window = window;
  return o;
}
FailureTest NinesFail() {
  return [](const std::vector<double>& f) { return f == std::vector<double>{9.0, 9.0}; };
}

TEST(SettlingRule, ASoundAnswerUnchangedForTheWindowSettlesWhileTheFrontMoves) {
  SettlingRule rule(SoundAnswer(1), OneDimension(), NinesFail());
  // The recommendation (lowest normalised sum: {1, 1}) stays; the rest of the front moves a lot.
  EXPECT_FALSE(rule.Update(0, {{3.0}, {4.0}, {5.0}}, {{1.0, 1.0}, {0.0, 5.0}, {5.0, 0.0}}));
  EXPECT_TRUE(rule.Update(1, {{3.0}, {4.0}, {5.0}}, {{1.0, 1.0}, {0.5, 4.0}, {4.0, 0.5}}));
  EXPECT_EQ(rule.settled_at(), 1u);
  EXPECT_THAT(rule.Describe(60), HasSubstr("stopped after generation 1 of 60: the recommended map was sound"));
  EXPECT_THAT(rule.Describe(60), HasSubstr("the same for 1 generation in a row"));
}

TEST(SettlingRule, AFailedOrChangingRecommendationIsNoSoundAnswer) {
  // Most individuals share a failed set: the recommendation is a failure, never settled on.
  SettlingRule failed(SoundAnswer(1), OneDimension(), NinesFail());
  for (unsigned g = 0; g <= 4; ++g) {
    EXPECT_FALSE(failed.Update(g, {{3.0}, {3.0}, {4.0}}, {{9.0, 9.0}, {9.0, 9.0}, {1.0 + g, 2.0}})) << g;
  }
  // A sound recommendation that changes every generation.
  SettlingRule changing(SoundAnswer(2), OneDimension(), NinesFail());
  EXPECT_FALSE(changing.Update(0, {{3.0}}, {{1.0, 1.0}}));
  EXPECT_FALSE(changing.Update(1, {{3.0}}, {{1.0, 1.0}}));  // once the same: the window is 2
  EXPECT_FALSE(changing.Update(2, {{4.0}}, {{0.5, 1.0}}));  // changed: counted afresh
  EXPECT_FALSE(changing.Update(3, {{4.0}}, {{0.5, 1.0}}));
  EXPECT_TRUE(changing.Update(4, {{4.0}}, {{0.5, 1.0}}));
  EXPECT_EQ(changing.settled_at(), 4u);
}

TEST(SettlingRule, TheSoundAnswerRuleIsOffByDefaultAndWithTheEarlyStop) {
  const Vectors x = {{3.0}, {4.0}, {5.0}};
  SettlingRule off(SettlingOptions{}, OneDimension(), NinesFail());
  SettlingOptions disabled = SoundAnswer(1);
  disabled.enabled = false;
  SettlingRule no_early_stop(disabled, OneDimension(), NinesFail());
  for (unsigned g = 0; g <= 6; ++g) {
    const double shift = 0.5 / (g + 1);  // the front keeps moving
    const Vectors f = {{1.0, 1.0}, {shift, 5.0}, {5.0, shift}};
    EXPECT_FALSE(off.Update(g, x, f)) << g;
    EXPECT_FALSE(no_early_stop.Update(g, x, f)) << g;
  }
  EXPECT_THROW(SettlingRule(SoundAnswer(-1), OneDimension()), InputError);
}

TEST(SettlingOptions, JsonRoundTripAndFoldersWithoutTheSoundAnswerRule) {
  SettlingOptions o = SoundAnswer(2);
  o.window = 4;
  const SettlingOptions back = SettlingOptions::FromJson(o.ToJson());
  EXPECT_EQ(back.sound_answer_window, 2);
  EXPECT_EQ(back.window, 4);
  // Off is not written, so settings stored before the rule existed compare equal.
  EXPECT_FALSE(SettlingOptions{}.ToJson().contains("sound_answer_window"));
  EXPECT_EQ(SettlingOptions::FromJson({{"enabled", true}, {"tolerance", 0.01}, {"window", 3}}).sound_answer_window, 0);
}

}  // namespace
}  // namespace slamtune::optim
