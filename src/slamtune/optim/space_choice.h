// The search space `slamtune optimize` takes when the user names none: r and g around the base
// configuration (loop closure, the seed paper's question) — unless the base configuration's own
// run shows its front end losing its place, or following the odometry along tens of metres of
// featureless corridor (slam/front_end_evidence.h). A map that breaks before
// any loop closes cannot be mended by loop-closure parameters, so the tuner then searches the
// front-end space (SearchSpace::FrontEnd) on its own: a user with a broken map should not need
// to know which parameters to add. A user who gives --space keeps that space.
#pragma once

#include <string>

#include "slamtune/optim/evaluation/slam_evaluation.h"
#include "slamtune/slam/front_end_evidence.h"

namespace slamtune::optim {

enum class DefaultSpaceKind { kLoop, kFrontEnd };

struct DefaultSpaceChoice {
  DefaultSpaceKind kind = DefaultSpaceKind::kLoop;
  slam::FrontEndEvidence evidence;               // of the base configuration's run
  std::vector<slam::SequentialMatchStep> steps;  // its sequential matches
  io::MapImage map;                              // its map (empty when the run failed)
  std::vector<io::TimedPose> trajectory;         // its poses, one per log scan
  // The --space name that reproduces the choice: "loop" or "front-end".
  const char* space_name() const { return kind == DefaultSpaceKind::kLoop ? "loop" : "front-end"; }
  // One line saying what was chosen and why.
  std::string Reason() const;
};

// The budget of the front-end search the tuner chooses for a broken map: the base run shows a
// break (not only a featureless stretch, where no run breaks and every map would count as sound)
// and the user gave no --population, --divisions or --sound-answer-window. The question is which parameters give a
// sound map, and each run of a wide search window is dear: a small population (12 individuals
// over the 10 reference points of 3 divisions), stopped once the recommendation is a sound map
// that two more generations did not change (settling.h). One generation is too few: generation
// 1 rarely beats the informed start's repaired set, which is sound but not yet good
// (docs/benchmarks.md, "A budget for a broken map").
struct BrokenMapBudget {
  std::size_t population = 12;
  std::size_t divisions = 3;
  int sound_answer_window = 2;
};

// Runs the base configuration once on `context` (one SLAM run; its matches go to the context's
// caches, so the optimisation repeats none of them) and chooses.
DefaultSpaceChoice ChooseDefaultSpace(const SlamEvaluationContext& context);

}  // namespace slamtune::optim
