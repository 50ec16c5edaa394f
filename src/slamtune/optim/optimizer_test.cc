#include "slamtune/optim/optimizer.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <filesystem>

#include "slamtune/common/error.h"
#include "slamtune/common/testing/temp_dir.h"

namespace slamtune::optim {
namespace {

// A cheap stand-in for a SLAM run with a three-way trade-off over (r, g).
EvaluationRecord FakeSlam(const Assignment& a) {
  const double r = a.at("loop_search_maximum_distance");
  const double g = a.at("loop_match_minimum_chain_size");
  EvaluationRecord rec;
  rec.occupied_ratio = 0.03 + 0.002 * std::pow(r - 4.5, 2) + 0.0001 * g;
  rec.corner_pixels = std::round(1000 + 30 * std::pow(g - 12, 2) + 5 * r);
  rec.enclosed_areas = std::round(5 + std::fabs(r - 3) + std::fabs(g - 15) / 3);
  rec.hits = 10000;
  // The unbacked-hit share runs against eta here, so the two objective sets disagree.
  rec.hits_in_free_cells = std::round(rec.hits * (0.5 - rec.occupied_ratio));
  rec.loop_closures = static_cast<int>(r);
  rec.nodes = 100;
  return rec;
}

std::string FreshStore(const std::string& name) {
  return (slamtune::testing::UniqueTempDir("opt_" + name) / "run.sqlite").string();
}

OptimizeSettings SmallSettings() {
  OptimizeSettings s;
  s.source.log_label = "fake.clf";
  s.population = 12;
  s.generations = 6;
  s.divisions = 4;
  s.seed = 3;
  s.default_assignment = {{"loop_search_maximum_distance", 4.0},
                          {"loop_match_minimum_chain_size", 10.0},
                          {"loop_match_minimum_response_coarse", 0.7},
                          {"loop_match_maximum_variance_coarse", 0.4}};
  return s;
}

OptimizeResult Optimize(const std::string& store_path, OptimizationStart start, EvaluateFn fn, int jobs = 2,
                        OptimizeSettings settings = SmallSettings()) {
  EvaluationStore store(store_path);
  BatchEvaluator evaluator(std::move(fn), &store, jobs);
  return RunOptimization(settings, evaluator, store, start, {});
}

std::vector<std::vector<double>> FinalPopulation(const std::string& store_path) {
  EvaluationStore store(store_path);
  return store.Generation(store.LastGeneration())->at("x").get<std::vector<std::vector<double>>>();
}

TEST(Optimizer, StartsByStoringSettingsAndCommandLineThenCallsStarted) {
  const std::string path = FreshStore("started");
  OptimizeSettings settings = SmallSettings();
  settings.generations = 1;
  settings.invocation = {{"seed", 3}, {"input_hashes", {{"log", "crc32:00000001"}}}};
  EvaluationStore store(path);
  BatchEvaluator evaluator(FakeSlam, &store, 1);
  int started = 0;
  OptimizeHooks hooks;
  hooks.started = [&] {
    ++started;
    if (started == 1) {
      EXPECT_EQ(store.Count(), 0u);  // before the first evaluation
    }
    EXPECT_TRUE(store.Settings().has_value());
  };
  RunOptimization(settings, evaluator, store, OptimizationStart::kNew, hooks);
  EXPECT_EQ(started, 1);
  EXPECT_EQ(*store.Meta("invocation"), settings.invocation);
  RunOptimization(settings, evaluator, store, OptimizationStart::kResume, hooks);  // resumed: called again
  EXPECT_EQ(started, 2);
}

TEST(Optimizer, RunsAndPicksTheFourCandidates) {
  const std::string path = FreshStore("basic");
  const OptimizeResult r = Optimize(path, OptimizationStart::kNew, FakeSlam);
  ASSERT_EQ(r.candidates.size(), 4u);
  EXPECT_EQ(r.candidates[0].label, "recommended");
  EXPECT_EQ(r.Find("default")->record.params.at("loop_search_maximum_distance"), 4.0);
  EXPECT_GE(r.recommended_share, 1);
  EXPECT_FALSE(r.verdict.empty());
  EXPECT_EQ(r.snapshots.size(), 3u);  // generations 1, 3, 6
  EXPECT_EQ(r.snapshots.back().generation, 6);
  // The history covers the initial population and every generation; the front only improves
  // on the objectives' common ranges when the survivors are elitist, so check its bounds.
  ASSERT_EQ(r.history.generations.size(), 7u);
  EXPECT_EQ(r.history.generations.front().generation, 0);
  EXPECT_EQ(r.history.generations.back().generation, 6);
  for (const auto& g : r.history.generations) {
    EXPECT_GT(g.hypervolume, 0.0);
    EXPECT_LE(g.hypervolume, 1.1 * 1.1 * 1.1);
    EXPECT_GE(g.front_size, 1);
    ASSERT_EQ(g.best.size(), 3u);
  }
  EXPECT_GE(r.history.generations.back().hypervolume, r.history.generations.front().hypervolume);
  // The recommendation is a member of its own equivalent region.
  ASSERT_TRUE(r.equivalent_region.has_value());
  EXPECT_GE(r.equivalent_region->members, 1u);
  EXPECT_EQ(r.equivalent_region->loop_closures, r.candidates[0].record.loop_closures);
  for (const ParameterRange& range : r.equivalent_region->ranges) {
    const double v = r.candidates[0].record.params.at(range.name);
    EXPECT_LE(range.lower, v);
    EXPECT_GE(range.upper, v);
  }
  for (const auto& e : r.evaluations) {
    const double g = e.params.at("loop_match_minimum_chain_size");
    EXPECT_EQ(g, std::round(g));
    EXPECT_GE(g, 6.0);
    EXPECT_LE(g, 20.0);
  }
  EvaluationStore store(path);
  EXPECT_EQ(store.LastGeneration(), 6);
  // A second run into the same folder without --resume is refused.
  EXPECT_THROW(Optimize(path, OptimizationStart::kNew, FakeSlam), InputError);
}

TEST(Optimizer, SameSeedSameResultWhateverTheJobs) {
  const std::string a = FreshStore("det_a"), b = FreshStore("det_b");
  Optimize(a, OptimizationStart::kNew, FakeSlam, 1);
  Optimize(b, OptimizationStart::kNew, FakeSlam, 3);
  EXPECT_EQ(FinalPopulation(a), FinalPopulation(b));
}

struct Killed {};  // not a std::exception: escapes the evaluator like a kill would stop it

TEST(Optimizer, ResumeAfterAKillMidGenerationGivesTheUninterruptedResult) {
  const std::string whole = FreshStore("whole"), cut = FreshStore("cut");
  const OptimizeResult reference = Optimize(whole, OptimizationStart::kNew, FakeSlam, 1);

  std::atomic<int> calls{0};
  EXPECT_THROW(Optimize(
                   cut, OptimizationStart::kNew,
                   [&](const Assignment& a) {
                     if (++calls == 40) throw Killed{};  // during generation 3 or so
                     return FakeSlam(a);
                   },
                   1),
               Killed);
  {
    EvaluationStore store(cut);
    EXPECT_GE(store.LastGeneration(), 1);
    EXPECT_LT(store.LastGeneration(), 6);
  }
  int resumed_calls = 0;
  const OptimizeResult resumed = Optimize(
      cut, OptimizationStart::kResume,
      [&](const Assignment& a) {
        ++resumed_calls;
        return FakeSlam(a);
      },
      1);
  EXPECT_EQ(FinalPopulation(whole), FinalPopulation(cut));
  EXPECT_EQ(resumed.candidates[0].record.key, reference.candidates[0].record.key);
  EXPECT_EQ(resumed.candidates[1].record.key, reference.candidates[1].record.key);
  EXPECT_EQ(resumed.evaluation_count, reference.evaluation_count);
  ASSERT_EQ(resumed.history.generations.size(), reference.history.generations.size());
  for (std::size_t g = 0; g < reference.history.generations.size(); ++g) {
    EXPECT_EQ(resumed.history.generations[g].hypervolume, reference.history.generations[g].hypervolume) << g;
  }
  EXPECT_LT(resumed_calls, static_cast<int>(reference.evaluation_count));  // finished work not redone
}

TEST(Optimizer, ResumeRefusesDifferentSettingsAndEmptyFolders) {
  const std::string path = FreshStore("settings");
  Optimize(path, OptimizationStart::kNew, FakeSlam);
  EvaluationStore store(path);
  BatchEvaluator evaluator(FakeSlam, &store, 1);
  OptimizeSettings other = SmallSettings();
  other.seed = 99;
  try {
    RunOptimization(other, evaluator, store, OptimizationStart::kResume, {});
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("different settings (seed)"), std::string::npos) << e.what();
    // What to do instead.
    EXPECT_NE(std::string(e.what()).find("--resume DIR alone continues it"), std::string::npos) << e.what();
  }
  EvaluationStore empty(FreshStore("empty"));
  BatchEvaluator ev2(FakeSlam, &empty, 1);
  EXPECT_THROW(RunOptimization(SmallSettings(), ev2, empty, OptimizationStart::kResume, {}), InputError);
}

TEST(Optimizer, FoldersWrittenBeforeObjectiveSetsResumeOnThePaperObjectives) {
  OptimizeSettings paper = SmallSettings();
  paper.objectives = ObjectiveSet(ObjectiveSetKind::kPaper);
  paper.generations = 2;
  const std::string path = FreshStore("old_folder");
  const OptimizeResult first = Optimize(path, OptimizationStart::kNew, FakeSlam, 1, paper);
  {
    EvaluationStore store(path);
    nlohmann::json settings = *store.Settings();
    settings.erase("objectives");  // as such a folder was written
    store.SetSettings(settings);
  }
  const OptimizeResult resumed = Optimize(path, OptimizationStart::kResume, FakeSlam, 1, paper);
  EXPECT_EQ(resumed.candidates[0].record.key, first.candidates[0].record.key);
  EXPECT_EQ(resumed.objectives.kind(), ObjectiveSetKind::kPaper);
  OptimizeSettings consistency = paper;
  consistency.objectives = ObjectiveSet(ObjectiveSetKind::kConsistency);
  try {
    Optimize(path, OptimizationStart::kResume, FakeSlam, 1, consistency);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("different settings (objectives)"), std::string::npos) << e.what();
  }
}

TEST(Optimizer, TheObjectiveSetDecidesWhatIsMinimised) {
  OptimizeSettings settings = SmallSettings();
  settings.generations = 1;
  const OptimizeResult consistency =
      Optimize(FreshStore("set_consistency"), OptimizationStart::kNew, FakeSlam, 1, settings);
  EXPECT_EQ(consistency.objectives.kind(), ObjectiveSetKind::kConsistency);
  ASSERT_FALSE(consistency.snapshots.empty());
  const GenerationSnapshot& snapshot = consistency.snapshots.front();
  for (std::size_t i = 0; i < snapshot.decisions.size(); ++i) {
    const EvaluationRecord rec = FakeSlam(settings.space.Assign(snapshot.decisions[i]));
    EXPECT_EQ(snapshot.objectives[i],
              (std::vector<double>{ValueOf(rec, Objective("unbacked_hits")), rec.corner_pixels, rec.enclosed_areas}));
  }
  settings.objectives = ObjectiveSet(ObjectiveSetKind::kPaper);
  const OptimizeResult paper = Optimize(FreshStore("set_paper"), OptimizationStart::kNew, FakeSlam, 1, settings);
  EXPECT_EQ(paper.snapshots.front().objectives.front()[0],
            FakeSlam(settings.space.Assign(paper.snapshots.front().decisions.front())).occupied_ratio);
}

// One integer parameter whose best value (g = 7) wins on every objective: the population
// fills with it and the answer settles long before the budget.
EvaluationRecord SettlingSlam(const Assignment& a) {
  const double g = a.at("loop_match_minimum_chain_size");
  EvaluationRecord rec;
  rec.occupied_ratio = 0.03 + 0.01 * std::fabs(g - 7);
  rec.corner_pixels = 1000 + 50 * std::fabs(g - 7);
  rec.enclosed_areas = 5 + std::fabs(g - 7);
  rec.hits = 10000;
  rec.hits_in_free_cells = 100 + 10 * std::fabs(g - 7);
  rec.nodes = 100;
  return rec;
}

OptimizeSettings SettlingSettings() {
  OptimizeSettings s = SmallSettings();
  s.space = SearchSpace();
  s.space.dimensions = {{"loop_match_minimum_chain_size", 6.0, 12.0, true}};
  s.default_assignment = {{"loop_match_minimum_chain_size", 10.0}};
  s.generations = 40;
  return s;
}

TEST(Optimizer, StopsOnceTheAnswerHasSettledAndAResumeStopsAtTheSameGeneration) {
  const OptimizeResult whole =
      Optimize(FreshStore("settle_whole"), OptimizationStart::kNew, SettlingSlam, 1, SettlingSettings());
  ASSERT_GT(whole.generations_run, 3u);
  EXPECT_LT(whole.generations_run, 40u);
  EXPECT_THAT(whole.settling, ::testing::HasSubstr("stopped after generation"));
  EXPECT_EQ(whole.candidates[0].record.params.at("loop_match_minimum_chain_size"), 7.0);
  EXPECT_EQ(whole.snapshots.back().generation, static_cast<int>(whole.generations_run));

  // Killed right after generation 2 is saved, before the answer settles.
  const std::string cut = FreshStore("settle_cut");
  {
    EvaluationStore store(cut);
    BatchEvaluator evaluator(SettlingSlam, &store, 1);
    OptimizeHooks hooks;
    hooks.progress = [](const std::string& line, bool force) {
      if (force && line.rfind("gen 2/", 0) == 0) throw Killed{};
    };
    EXPECT_THROW(RunOptimization(SettlingSettings(), evaluator, store, OptimizationStart::kNew, hooks), Killed);
    EXPECT_EQ(store.LastGeneration(), 2);
  }
  const OptimizeResult resumed = Optimize(cut, OptimizationStart::kResume, SettlingSlam, 1, SettlingSettings());
  EXPECT_EQ(resumed.generations_run, whole.generations_run);
  EXPECT_EQ(resumed.settling, whole.settling);
  EXPECT_EQ(resumed.candidates[0].record.key, whole.candidates[0].record.key);
  ASSERT_EQ(resumed.snapshots.size(), whole.snapshots.size());
  for (std::size_t i = 0; i < whole.snapshots.size(); ++i) {
    EXPECT_EQ(resumed.snapshots[i].generation, whole.snapshots[i].generation);
  }
  // Resuming a settled run again runs nothing more.
  const OptimizeResult again = Optimize(cut, OptimizationStart::kResume, SettlingSlam, 1, SettlingSettings());
  EXPECT_EQ(again.generations_run, whole.generations_run);

  OptimizeSettings fixed = SettlingSettings();
  fixed.generations = 12;
  fixed.settling.enabled = false;
  const OptimizeResult full = Optimize(FreshStore("settle_fixed"), OptimizationStart::kNew, SettlingSlam, 1, fixed);
  EXPECT_EQ(full.generations_run, 12u);
  EXPECT_EQ(full.settling, "ran the fixed budget of 12 generations");
}

TEST(Optimizer, TheSoundAnswerRuleStopsOnceTheRecommendationHoldsAndAResumeAgrees) {
  // FakeSlam's three-way trade-off keeps the front moving; its recommendation holds sooner.
  OptimizeSettings sound = SmallSettings();
  sound.generations = 30;
  sound.settling.sound_answer_window = 2;
  OptimizeSettings front_only = sound;
  front_only.settling.sound_answer_window = 0;
  const OptimizeResult whole = Optimize(FreshStore("sound_whole"), OptimizationStart::kNew, FakeSlam, 1, sound);
  const OptimizeResult front = Optimize(FreshStore("sound_front"), OptimizationStart::kNew, FakeSlam, 1, front_only);
  EXPECT_THAT(whole.settling, ::testing::HasSubstr("the recommended map was sound"));
  EXPECT_GE(whole.generations_run, 2u);  // counted from generation 0: at least 0, 1 and 2
  EXPECT_LT(whole.generations_run, front.generations_run);

  // Killed right after generation 1 is saved: the resumed run replays generations 0 and 1
  // through the rule and stops where the uninterrupted one did.
  const std::string cut = FreshStore("sound_cut");
  {
    EvaluationStore store(cut);
    BatchEvaluator evaluator(FakeSlam, &store, 1);
    OptimizeHooks hooks;
    hooks.progress = [](const std::string& line, bool force) {
      if (force && line.rfind("gen 1/", 0) == 0) throw Killed{};
    };
    EXPECT_THROW(RunOptimization(sound, evaluator, store, OptimizationStart::kNew, hooks), Killed);
  }
  const OptimizeResult resumed = Optimize(cut, OptimizationStart::kResume, FakeSlam, 1, sound);
  EXPECT_EQ(resumed.generations_run, whole.generations_run);
  EXPECT_EQ(resumed.settling, whole.settling);
  EXPECT_EQ(resumed.candidates[0].record.key, whole.candidates[0].record.key);
}

TEST(Optimizer, StopsWithAReadableErrorWhenEveryRunFails) {
  const std::string path = FreshStore("all_failed");
  const EvaluateFn fail = [](const Assignment& a) {
    return EvaluationRecord::Failed("", a, "mapper parameter x = 1 is out of range");
  };
  try {
    Optimize(path, OptimizationStart::kNew, fail);
    FAIL() << "an optimisation of failed runs returned";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("every SLAM run of the initial population failed"), std::string::npos)
        << e.what();
    EXPECT_NE(std::string(e.what()).find("out of range"), std::string::npos) << e.what();
  }
}

TEST(Optimizer, RejectsBadBudgets) {
  OptimizeSettings s = SmallSettings();
  s.population = 2;
  EXPECT_THROW(s.Validate(), InputError);
  s = SmallSettings();
  s.generations = 0;
  EXPECT_THROW(s.Validate(), InputError);
}

}  // namespace
}  // namespace slamtune::optim
