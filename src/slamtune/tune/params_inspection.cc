#include "slamtune/tune/params_inspection.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "slamtune/common/text_file.h"
#include "slamtune/slam/params/base_configuration.h"
#include "slamtune/slam/params/mapper_param_rows.h"
#include "slamtune/slam/params/ros_params_section.h"

namespace slamtune::tune {
namespace {

nlohmann::ordered_json KeysJson(const slam::ParamsYamlReport& report) {
  nlohmann::ordered_json keys = nlohmann::ordered_json::array();
  for (const slam::KeyReport& k : report.keys) {
    keys.push_back({{"key", k.key}, {"line", k.line}, {"use", slam::NameOf(k.use)}, {"note", k.note}});
  }
  return keys;
}

}  // namespace

bool ParamsInspection::AllLoad() const {
  for (const ParamsFileCheck& f : files) {
    if (!f.problems.empty()) return false;
  }
  return true;
}

ParamsInspection InspectParamsFiles(const std::vector<std::string>& files, const std::string& preset,
                                    const std::vector<std::string>& sets) {
  slam::BaseConfiguration base = slam::LoadBaseConfiguration(files.front(), preset, {});
  ParamsInspection out;
  out.files.push_back(
      {files.front(), base.file_text, base.node, slam::CheckNodeFile(base.node, base.file_text), base.file_report});
  for (std::size_t i = 1; i < files.size(); ++i) {
    ParamsFileCheck check;
    check.path = files[i];
    check.text = ReadTextFile(files[i]);
    check.node = slam::NodeOfParamsFile(check.text, files[i]);
    check.report = slam::ApplyParamsYaml(base.params, check.text, files[i]);
    check.problems = slam::CheckNodeFile(check.node, check.text);
    out.files.push_back(std::move(check));
  }
  slam::ApplyOverrides(base.params, sets);
  base.params.Validate();
  out.params = base.params;
  out.defaults = slam::NodeDefaults(base.node);
  out.defaults.node_mode = base.params.node_mode;
  out.defaults_label =
      fmt::format("{}'s declared defaults, {}", slam::RosNodeName(base.node), slam::LaunchOf(base.params.node_mode));
  return out;
}

nlohmann::ordered_json ToJson(const ParamsInspection& inspection, bool all) {
  nlohmann::ordered_json j;
  j["files"] = nlohmann::ordered_json::array();
  for (const ParamsFileCheck& c : inspection.files) {
    j["files"].push_back({{"path", c.path},
                          {"node", slam::RosNodeName(c.node)},
                          {"loads", c.problems.empty()},
                          {"problems", c.problems},
                          {"keys", KeysJson(c.report)}});
  }
  j["node_mode"] = slam::NameOf(inspection.params.node_mode);
  j["over"] = inspection.defaults_label;
  const std::vector<slam::NamedParam> values = slam::ToNamedValues(inspection.params);
  const std::vector<slam::NamedParam> defaults = slam::ToNamedValues(inspection.defaults);
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (!all && values[i].value == defaults[i].value) continue;
    std::visit([&](const auto& v) { params[values[i].name] = v; }, values[i].value);
  }
  j["params"] = params;
  return j;
}

std::vector<ListedParam> ListedParams(const ParamsInspection& inspection, bool all) {
  const std::vector<slam::NamedParam> values = slam::ToNamedValues(inspection.params);
  const std::vector<slam::NamedParam> defaults = slam::ToNamedValues(inspection.defaults);
  std::vector<ListedParam> out;
  for (std::size_t i = 0; i < values.size(); ++i) {
    const bool differs = values[i].value != defaults[i].value;
    if (all || differs) out.push_back({values[i].name, slam::ParamValueText(values[i].value), differs});
  }
  return out;
}

std::vector<std::string> WrittenValues(const ParamsFileCheck& check) {
  const YAML::Node root = YAML::Load(check.text);
  const YAML::Node map = slam::FindParamsSection(root, "file").map;
  std::vector<std::string> out;
  for (const slam::KeyReport& k : check.report.keys) {
    const YAML::Node value = map[k.key];
    out.push_back(value.IsScalar() ? value.Scalar() : "[...]");
  }
  return out;
}

}  // namespace slamtune::tune
