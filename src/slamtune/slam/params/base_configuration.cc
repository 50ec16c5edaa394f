#include "slamtune/slam/params/base_configuration.h"

#include <fmt/format.h>

#include <filesystem>
#include <regex>

#include "slamtune/common/error.h"
#include "slamtune/common/text_file.h"

namespace slamtune::slam {
namespace {

// The mode a file written by `slamtune optimize` was tuned for, from its first line
// ("# slamtune optimize, tuned for slam_toolbox_sync (...)"); "" for any other file.
std::string TunedForMode(const std::string& text) {
  static const std::regex kTunedFor("^# slamtune optimize, tuned for ([a-z_]+) ");
  std::smatch m;
  const std::string first = text.substr(0, text.find('\n'));
  if (!std::regex_search(first, m, kTunedFor)) return "";
  const std::string mode = m[1];
  for (const std::string& preset : PresetNames()) {
    if (preset == mode || (mode == "slam_toolbox_async" && preset == "slam_toolbox")) return preset;
  }
  return "";
}

// The defaults under a file written for `node`, in the mode `preset` names.
MapperParams DefaultsUnderFile(RosNode node, const std::string& preset, const std::string& file) {
  if (!preset.empty() && NodeOfPreset(preset) != node) {
    throw InputError(file, 0,
                     node == RosNode::kSlamToolbox
                         ? fmt::format("a slam_toolbox (ROS 2) parameter file, but --preset {} is slam_karto's: give "
                                       "--preset slam_toolbox, slam_toolbox_sync or slam_toolbox_offline (the node's "
                                       "mode), or none",
                                       preset)
                         : fmt::format("a slam_karto (flat) parameter file, but --preset {} is slam_toolbox's: a "
                                       "slam_toolbox file nests its parameters as slam_toolbox: ros__parameters:",
                                       preset));
  }
  MapperParams params = NodeDefaults(node);
  if (node == RosNode::kSlamToolbox && !preset.empty()) params.node_mode = MapperParams::Preset(preset).node_mode;
  return params;
}

}  // namespace

RosNode NodeOfPreset(const std::string& preset) {
  MapperParams::Preset(preset);  // InputError for an unknown name
  return preset.rfind("slam_toolbox", 0) == 0 ? RosNode::kSlamToolbox : RosNode::kSlamKarto;
}

BaseConfiguration LoadBaseConfiguration(const std::string& params_file, const std::string& preset,
                                        const std::vector<std::string>& sets, BaseRule rule) {
  BaseConfiguration base;
  if (params_file.empty()) {
    const std::string name = preset.empty() ? "slam_karto" : preset;
    base.params = MapperParams::Preset(name);
    base.node = NodeOfPreset(name);
    base.mode_source = preset.empty() ? "default" : "--preset";
    base.label = name + "'s defaults";
  } else {
    base.file_text = ReadTextFile(params_file);
    base.node = NodeOfParamsFile(base.file_text, params_file);
    std::string mode = preset;
    base.mode_source = preset.empty() ? "default" : "--preset";
    if (const std::string tuned = TunedForMode(base.file_text); preset.empty() && !tuned.empty()) {
      if (NodeOfPreset(tuned) == base.node) {
        mode = tuned;
        base.mode_source = std::filesystem::path(params_file).filename().string() + "'s first comment";
      }
    }
    base.params = rule == BaseRule::kPresetThenFile && !preset.empty()
                      ? MapperParams::Preset(preset)
                      : DefaultsUnderFile(base.node, mode, params_file);
    base.file_report = ApplyParamsYaml(base.params, base.file_text, params_file);
    base.label = "your configuration (" + std::filesystem::path(params_file).filename().string() + ")";
  }
  ApplyOverrides(base.params, sets);
  if (!sets.empty()) base.label += " with --set";
  base.params.Validate();
  return base;
}

}  // namespace slamtune::slam
