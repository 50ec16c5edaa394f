#include "slamtune/optim/stored_settings.h"

#include "slamtune/optim/objective_set.h"
#include "slamtune/optim/settling.h"

namespace slamtune::optim {
namespace {

// Adds to `stored` every key of `current` it lacks, at any depth of objects.
void AddMissingKeys(const nlohmann::json& current, nlohmann::json& stored) {
  if (!current.is_object() || !stored.is_object()) return;
  for (const auto& [key, value] : current.items()) {
    if (!stored.contains(key)) {
      stored[key] = value;
    } else {
      AddMissingKeys(value, stored[key]);
    }
  }
}

}  // namespace

nlohmann::json UpgradeStoredSettings(nlohmann::json stored, const nlohmann::json& current) {
  if (stored.is_object() && stored.contains("engine") && current.contains("engine")) {
    AddMissingKeys(current.at("engine"), stored["engine"]);
  }
  // Before objective sets, the paper's objectives.
  if (stored.is_object() && !stored.contains("objectives")) {
    stored["objectives"] = ObjectiveSet::NameOf(ObjectiveSetKind::kPaper);
  }
  // Before early stopping, a run went through its whole budget.
  if (stored.is_object() && !stored.contains("settling")) {
    stored["settling"] = SettlingOptions{false}.ToJson();
  }
  return stored;
}

}  // namespace slamtune::optim
