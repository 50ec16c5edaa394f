#include "slamtune/cli/command_registry.h"

namespace slamtune::cli {

std::vector<Subcommand>& Registry() {
  static std::vector<Subcommand> registry;
  return registry;
}

SubcommandRegistrar::SubcommandRegistrar(Subcommand command) { Registry().push_back(std::move(command)); }

}  // namespace slamtune::cli
