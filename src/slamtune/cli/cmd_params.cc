// `slamtune params FILE...`: what a slam_toolbox or slam_karto parameter file means to the
// engine, and whether its node would load it (tune/params_inspection.h). Several files are
// applied in order, as a launch file stacks them (your file, then a change file).
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "slamtune/cli/command_registry.h"
#include "slamtune/tune/params_inspection.h"

namespace slamtune::cli {
namespace {

struct ParamsArgs {
  std::vector<std::string> files;
  std::string preset;
  std::vector<std::string> sets;
  bool all = false;
  bool json = false;
};

// One line per key: name, value as written, what it means to the engine.
void PrintKeys(const tune::ParamsFileCheck& check) {
  const std::vector<std::string> written = tune::WrittenValues(check);
  for (std::size_t i = 0; i < written.size(); ++i) {
    const slam::KeyReport& k = check.report.keys[i];
    std::printf("  %-42s %-24s %s%s%s\n", k.key.c_str(), written[i].c_str(), slam::NameOf(k.use),
                k.note.empty() ? "" : ": ", k.note.c_str());
  }
}

void PrintFiles(const tune::ParamsInspection& inspection) {
  for (const tune::ParamsFileCheck& c : inspection.files) {
    std::printf("%s: a %s (%s) parameter file; %s\n", c.path.c_str(), slam::RosNodeName(c.node),
                c.node == slam::RosNode::kSlamToolbox ? "ROS 2" : "ROS 1",
                c.problems.empty() ? "the node loads it" : "the node would not take it as it is:");
    for (const std::string& p : c.problems) std::printf("  %s\n", p.c_str());
    if (!c.report.keys.empty()) {
      std::printf("what each key means here:\n");
      PrintKeys(c);
    }
  }
}

int RunParams(const ParamsArgs& args) {
  const tune::ParamsInspection inspection = tune::InspectParamsFiles(args.files, args.preset, args.sets);
  const int status = inspection.AllLoad() ? 0 : 1;
  if (args.json) {
    std::printf("%s\n", tune::ToJson(inspection, args.all).dump(2).c_str());
    return status;
  }
  PrintFiles(inspection);
  std::printf("engine parameters over %s (%s):\n", inspection.defaults_label.c_str(),
              args.all ? "all; * = differs" : "those that differ");
  for (const tune::ListedParam& p : tune::ListedParams(inspection, args.all)) {
    std::printf("  %-42s %s%s\n", p.name.c_str(), p.value.c_str(), args.all && p.differs ? " *" : "");
  }
  return status;
}

const SubcommandRegistrar kParams(Subcommand{
    "params",
    "What slam_toolbox / slam_karto parameter files mean to the engine, and whether the node loads them "
    "(exit 1 if not)",
    70,
    [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<ParamsArgs>();
      app.add_option("FILE", args->files,
                     "parameter files, applied in order (e.g. your file, then best_change.yaml); the first one's "
                     "layout names the node: ros__parameters = slam_toolbox, flat = slam_karto")
          ->required();
      app.add_option("--preset", args->preset,
                     "the node's mode (slam_toolbox, slam_toolbox_sync, slam_toolbox_offline; slam_karto): some keys "
                     "mean something only to the synchronous node");
      app.add_option("--set", args->sets, "override one parameter, NAME=VALUE (repeatable; applied last)");
      app.add_flag("--all", args->all, "list every engine parameter, not only those that differ from the defaults");
      app.add_flag("--json", args->json, "machine-readable output");
      app.footer(
          "Examples:\n"
          "  slamtune params my_slam_toolbox.yaml\n"
          "  slamtune params my_slam_toolbox.yaml runs/office/best_change.yaml --json");
      return [args] { return RunParams(*args); };
    },
});

}  // namespace
}  // namespace slamtune::cli
