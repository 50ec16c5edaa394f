// The settings a run database holds (OptimizeSettings::ToJson, compared on --resume), read as
// today's ToJson writes them. Folders written before objective sets existed were optimised on the
// paper's objectives and ran their whole budget; a parameter or input option that did not exist
// when the folder was written had the value it has today (the engine's behaviour then; `current`
// gives it). The command's own record of a run (its invocation) is migrated by
// tune::MigrateInvocation.
#pragma once

#include <nlohmann/json.hpp>

namespace slamtune::optim {

// `stored` upgraded to the layout of `current` (the settings of the run being resumed).
nlohmann::json UpgradeStoredSettings(nlohmann::json stored, const nlohmann::json& current);

}  // namespace slamtune::optim
