#include "slamtune/cli/result_neutral_options.h"

#include <algorithm>

namespace slamtune::cli {

CLI::Option* ResultNeutralOptions::Add(CLI::Option* option) {
  options_.push_back(option);
  return option;
}

void ResultNeutralOptions::Add(const std::vector<CLI::Option*>& options) {
  for (CLI::Option* option : options) Add(option);
}

bool ResultNeutralOptions::OnlyTheseGiven(const CLI::App& app) const {
  for (const CLI::Option* option : app.get_options()) {
    if (option->count() > 0 && std::find(options_.begin(), options_.end(), option) == options_.end()) return false;
  }
  return true;
}

}  // namespace slamtune::cli
