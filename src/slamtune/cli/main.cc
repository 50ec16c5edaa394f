// slamtune: tune Karto / slam_toolbox loop closure without ground truth.
//
// Thin entry point: builds the CLI from the registered subcommands, runs the chosen one
// and turns user-input errors into one line on stderr and a non-zero exit.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstdio>
#include <exception>
#include <memory>
#include <new>

#include "slamtune/cli/command_registry.h"
#include "slamtune/common/error.h"

int main(int argc, char** argv) {
  using slamtune::cli::Registry;
  CLI::App app{
      "slamtune: tune Karto / slam_toolbox 2D graph SLAM without ground truth.\n"
      "Runs a Karto-faithful SLAM engine on your recording, scores its maps by how well the scans agree\n"
      "with the map, Harris corners and enclosed areas, finds where the front end broke, and searches\n"
      "the loop-closure (or front-end) parameters with NSGA-III."};
  app.require_subcommand(1);
  app.set_version_flag("--version", "slamtune 0.1.0");

  auto& commands = Registry();
  std::stable_sort(commands.begin(), commands.end(), [](const auto& a, const auto& b) { return a.order < b.order; });
  std::function<int()> action;
  for (auto& command : commands) {
    CLI::App* sub = app.add_subcommand(command.name, command.description);
    auto run = command.setup(*sub);
    sub->callback([&action, run] { action = run; });
  }

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    // --help and --version end here with exit 0; a command line that cannot be read is bad input.
    if (e.get_exit_code() == 0) return app.exit(e);
    std::fprintf(stderr, "slamtune: error: %s (see slamtune --help, or slamtune COMMAND --help)\n", e.what());
    return 2;
  } catch (const slamtune::InputError& e) {
    std::fprintf(stderr, "slamtune: error: %s\n", e.what());
    return 2;
  }
  try {
    return action ? action() : 1;
  } catch (const slamtune::InputError& e) {
    std::fprintf(stderr, "slamtune: error: %s\n", e.what());
    return 2;
  } catch (const std::bad_alloc&) {
    std::fprintf(stderr, "slamtune: error: out of memory\n");
    return 3;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "slamtune: error: %s\n", e.what());
    return 1;
  }
}
