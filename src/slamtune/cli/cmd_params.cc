// `slamtune params FILE...`: what a slam_toolbox or slam_karto parameter file means to the
// engine, and whether its node would load it (slam/ros_node_files.h CheckNodeFile). Several
// files are applied in order, as a launch file stacks them (your file, then a change file).
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slamtune/cli/command_registry.h"
#include "slamtune/cli/input_flags.h"
#include "slamtune/common/text_file.h"
#include "slamtune/slam/base_configuration.h"
#include "slamtune/slam/params_yaml.h"
#include "slamtune/slam/ros_node_files.h"
#include "slamtune/slam/ros_params_section.h"

namespace slamtune::cli {
namespace {

struct ParamsArgs {
  std::vector<std::string> files;
  std::string preset;
  std::vector<std::string> sets;
  bool all = false;
  bool json = false;
};

struct FileCheck {
  std::string path;
  slam::RosNode node;
  std::vector<std::string> problems;
  slam::ParamsYamlReport report;  // what each key means to the engine
};

std::string ValueText(const slam::ParamValue& value) {
  return std::visit(
      [](const auto& v) -> std::string {
        using T = std::decay_t<decltype(v)>;
        if constexpr (std::is_same_v<T, std::string>) {
          return v;
        } else if constexpr (std::is_same_v<T, bool>) {
          return v ? "true" : "false";
        } else {
          return fmt::format("{}", v);
        }
      },
      value);
}

// One line per key: name, value as written, what it means to the engine.
void PrintKeys(const slam::ParamsYamlReport& report, const std::string& text) {
  YAML::Node root = YAML::Load(text);
  const YAML::Node map = slam::FindParamsSection(root, "file").map;
  for (const slam::KeyReport& k : report.keys) {
    const YAML::Node value = map[k.key];
    const std::string shown = value.IsScalar() ? value.Scalar() : "[...]";
    std::printf("  %-42s %-24s %s%s%s\n", k.key.c_str(), shown.c_str(), slam::NameOf(k.use), k.note.empty() ? "" : ": ",
                k.note.c_str());
  }
}

nlohmann::ordered_json KeysJson(const slam::ParamsYamlReport& report) {
  nlohmann::ordered_json keys = nlohmann::ordered_json::array();
  for (const slam::KeyReport& k : report.keys) {
    keys.push_back({{"key", k.key}, {"line", k.line}, {"use", slam::NameOf(k.use)}, {"note", k.note}});
  }
  return keys;
}

int RunParams(const ParamsArgs& args) {
  slam::BaseConfiguration base = slam::LoadBaseConfiguration(args.files.front(), args.preset, {});
  std::vector<FileCheck> checks;
  checks.push_back({args.files.front(), base.node, slam::CheckNodeFile(base.node, base.file_text), base.file_report});
  std::vector<std::string> texts = {base.file_text};
  for (std::size_t i = 1; i < args.files.size(); ++i) {
    texts.push_back(ReadTextFile(args.files[i]));
    const slam::RosNode node = slam::NodeOfParamsFile(texts.back(), args.files[i]);
    slam::ParamsYamlReport report = slam::ApplyParamsYaml(base.params, texts.back(), args.files[i]);
    checks.push_back({args.files[i], node, slam::CheckNodeFile(node, texts.back()), std::move(report)});
  }
  slam::ApplyOverrides(base.params, args.sets);
  base.params.Validate();

  slam::MapperParams defaults = slam::NodeDefaults(base.node);
  defaults.node_mode = base.params.node_mode;
  const std::string defaults_label =
      fmt::format("{}'s declared defaults, {}", slam::RosNodeName(base.node), slam::LaunchOf(base.params.node_mode));
  const std::vector<slam::NamedParam> values = slam::ToNamedValues(base.params);
  const std::vector<slam::NamedParam> default_values = slam::ToNamedValues(defaults);
  bool all_load = true;
  for (const FileCheck& c : checks) all_load = all_load && c.problems.empty();

  if (args.json) {
    nlohmann::ordered_json j;
    j["files"] = nlohmann::ordered_json::array();
    for (const FileCheck& c : checks) {
      j["files"].push_back({{"path", c.path},
                            {"node", slam::RosNodeName(c.node)},
                            {"loads", c.problems.empty()},
                            {"problems", c.problems},
                            {"keys", KeysJson(c.report)}});
    }
    j["node_mode"] = slam::NameOf(base.params.node_mode);
    j["over"] = defaults_label;
    nlohmann::ordered_json params = nlohmann::ordered_json::object();
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (!args.all && values[i].value == default_values[i].value) continue;
      std::visit([&](const auto& v) { params[values[i].name] = v; }, values[i].value);
    }
    j["params"] = params;
    std::printf("%s\n", j.dump(2).c_str());
    return all_load ? 0 : 1;
  }
  for (std::size_t i = 0; i < checks.size(); ++i) {
    const FileCheck& c = checks[i];
    std::printf("%s: a %s (%s) parameter file; %s\n", c.path.c_str(), slam::RosNodeName(c.node),
                c.node == slam::RosNode::kSlamToolbox ? "ROS 2" : "ROS 1",
                c.problems.empty() ? "the node loads it" : "the node would not take it as it is:");
    for (const std::string& p : c.problems) std::printf("  %s\n", p.c_str());
    if (!c.report.keys.empty()) {
      std::printf("what each key means here:\n");
      PrintKeys(c.report, texts[i]);
    }
  }
  std::printf("engine parameters over %s (%s):\n", defaults_label.c_str(),
              args.all ? "all; * = differs" : "those that differ");
  for (std::size_t i = 0; i < values.size(); ++i) {
    const bool differs = values[i].value != default_values[i].value;
    if (!args.all && !differs) continue;
    std::printf("  %-42s %s%s\n", values[i].name.c_str(), ValueText(values[i].value).c_str(),
                args.all && differs ? " *" : "");
  }
  return all_load ? 0 : 1;
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
