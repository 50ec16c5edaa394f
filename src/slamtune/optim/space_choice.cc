#include "slamtune/optim/space_choice.h"

#include <fmt/format.h>

namespace slamtune::optim {

std::string DefaultSpaceChoice::Reason() const {
  if (kind == DefaultSpaceKind::kFrontEnd) {
    return "search space: front-end (sequential matching, node spacing and loop closure), because a run of the "
           "base configuration shows its front end failing where no loop closure can mend it — " +
           evidence.Summary();
  }
  return "search space: r and g around the base configuration (" + evidence.Summary() + ")";
}

DefaultSpaceChoice ChooseDefaultSpace(const SlamEvaluationContext& context) {
  SlamRun run;
  const EvaluationRecord base = EvaluateSlam(context, {}, &run);
  DefaultSpaceChoice choice;
  choice.evidence = run.front_end;
  choice.steps = std::move(run.sequential_matches);
  choice.map = std::move(run.map);
  choice.trajectory = std::move(run.trajectory);
  if (base.status == RunStatus::kOk && run.front_end.points_at_front_end()) choice.kind = DefaultSpaceKind::kFrontEnd;
  return choice;
}

}  // namespace slamtune::optim
