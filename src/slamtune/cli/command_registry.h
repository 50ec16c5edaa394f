// Self-registration of CLI subcommands.
//
// Each subcommand lives in its own cmd_<name>.cc and registers itself with a static
// SubcommandRegistrar, so adding a command never touches main. Commands are compiled
// straight into the `slamtune` executable (not into libslamtune), so the registrars are
// never dropped by the linker.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>
#include <vector>

namespace slamtune::cli {

// A subcommand: `setup` adds its options to `app` (already created with name and
// description) and returns the action to run after parsing. The action returns the
// process exit code; it may throw InputError for bad input (printed as one line, exit 2).
struct Subcommand {
  std::string name;
  std::string description;
  int order = 100;  // position in --help
  std::function<std::function<int()>(CLI::App& app)> setup;
};

std::vector<Subcommand>& Registry();

struct SubcommandRegistrar {
  explicit SubcommandRegistrar(Subcommand command);
};

}  // namespace slamtune::cli
