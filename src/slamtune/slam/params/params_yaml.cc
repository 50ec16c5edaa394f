#include "slamtune/slam/params/params_yaml.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <optional>
#include <string_view>

#include "slamtune/common/error.h"
#include "slamtune/common/text_file.h"
#include "slamtune/io/yaml_text.h"
#include "slamtune/slam/backend/ceres_solver.h"
#include "slamtune/slam/params/ros_node_files.h"
#include "slamtune/slam/params/ros_params_section.h"

namespace slamtune::slam {
namespace {

// A key of a slam_toolbox or slam_karto node configuration that does not change what the engine
// computes from a log (frames, topics, publication periods, interactive modes, ...).
bool IsNodeOnlyKey(const std::string& key) {
  for (RosNode node : {RosNode::kSlamToolbox, RosNode::kSlamKarto}) {
    const NodeParam* param = FindNodeParam(node, key);
    if (param != nullptr && param->engine[0] == '\0') return true;
  }
  return false;
}

SolverKind SolverFromPlugin(const std::string& plugin, const std::string& source) {
  if (plugin.find("Ceres") != std::string::npos) return SolverKind::kCeres;
  if (plugin.find("Spa") != std::string::npos) return SolverKind::kSpa;
  throw InputError(source, 0,
                   fmt::format("solver_plugin '{}' is not supported: must be solver_plugins::CeresSolver or "
                               "solver_plugins::SpaSolver",
                               plugin));
}

// What slam_toolbox's CeresSolver::Configure uses for a text it does not know, per ceres_* key
// (the first value of each enum, pose_graph_solver.h); nullptr for other keys.
const char* CeresFallback(std::string_view key) {
  if (key == "ceres_loss_function") return NameOf(CeresLoss::kNone);
  if (key == "ceres_linear_solver") return NameOf(CeresLinearSolver::kSparseNormalCholesky);
  if (key == "ceres_preconditioner") return NameOf(CeresPreconditioner::kJacobi);
  if (key == "ceres_trust_strategy") return NameOf(CeresTrustStrategy::kLevenbergMarquardt);
  if (key == "ceres_dogleg_type") return NameOf(CeresDoglegType::kTraditional);
  return nullptr;
}

// Whether `text` names a value of the choice parameter `key`.
bool NamesAChoice(const std::string& key, const std::string& text) {
  MapperParams probe;
  UnknownChoices unknown;
  AssignFromString(probe, key, text, &unknown);
  return unknown.empty();
}

// Keys of a slam_toolbox file that change what the node maps in ways the engine does not
// reproduce, with why; nullptr for other keys and values.
const char* NotModelledToolboxKey(const std::string& key, const std::string& text) {
  if (key == "mode" && text != "mapping") {
    return "the node localizes in a saved map in this mode; slamtune maps from scratch";
  }
  if (key == "map_file_name" || key == "map_start_pose" || key == "map_start_at_dock") {
    return "the node continues a saved map with it; slamtune maps from scratch";
  }
  return nullptr;
}

// Reads one file's section into `copy`, key by key.
class SectionReader {
 public:
  SectionReader(MapperParams& copy, bool ros2, const std::string& source) : copy_(copy), ros2_(ros2), source_(source) {}

  void Read(const std::string& key, const YAML::Node& value, bool have_resolution) {
    KeyReport r{key, LineOf(value), KeyUse::kEngine, ""};
    if (!value.IsScalar()) {
      if (!IsNodeOnlyKey(key)) throw InputError(source_, r.line, fmt::format("parameter {} must be a scalar", key));
      ClassifyNodeKey(r, "");
      return Add(std::move(r));
    }
    const std::string text = value.Scalar();
    try {
      if (ros2_ ? ReadToolboxKey(r, text) : ReadKartoKey(r, text)) return Add(std::move(r));
      if (key == "solver_plugin") {
        copy_.solver = SolverFromPlugin(text, source_);
        Apply(r, "solver");
      } else if (key == "delta") {  // slam_karto's fallback name for the map resolution
        if (have_resolution) {
          Ignore(r, "resolution is set too, and wins");
        } else {
          AssignFromString(copy_, "resolution", text, &unknown_choices_);
          Apply(r, "resolution");
        }
      } else if (FindParam(key) != nullptr) {
        AssignFromString(copy_, key, text, &unknown_choices_);
        Apply(r, key);
      } else if (IsNodeOnlyKey(key)) {
        ClassifyNodeKey(r, text);
      } else {
        throw InputError(UnknownParamMessage(key));
      }
    } catch (const InputError& e) {
      throw InputError(source_, r.line, e.message());
    }
    Add(std::move(r));
  }

  // After the last key: what depends on several keys, then the report.
  ParamsYamlReport Finish() {
    if (ros2_ && transform_timeout_ && !has_minimum_time_interval_) {
      // slam_toolbox_common.cpp declares minimum_time_interval with transform_timeout's value.
      copy_.sync_minimum_time_interval = *transform_timeout_;
      KeyReport& r = report_.keys[transform_timeout_key_];
      if (IsSynchronous(copy_.node_mode)) {
        r.use = KeyUse::kEngine;
        r.note = "also the synchronous node's minimum_time_interval, which the file leaves out";
        report_.applied.push_back("sync_minimum_time_interval");
      }
    }
    if (ros2_ && copy_.solver == SolverKind::kCeres) {
      if (const std::string why = CeresChoicesProblem(copy_.Ceres()); !why.empty()) {
        report_.warnings.push_back(
            fmt::format("{}: Ceres refuses these ceres_* options ({}): every solve of the "
                        "node fails, and no loop closure corrects its map",
                        source_, why));
      }
    }
    return std::move(report_);
  }

  const UnknownChoices& unknown_choices() const { return unknown_choices_; }

 private:
  // slam_toolbox's own readings of a key; false for keys read as everywhere else.
  bool ReadToolboxKey(KeyReport& r, const std::string& text) {
    const std::string& key = r.key;
    const bool sync = IsSynchronous(copy_.node_mode);
    if (key == "minimum_time_interval") {
      AssignFromString(copy_, "sync_minimum_time_interval", text);
      has_minimum_time_interval_ = true;
      if (sync) {
        Apply(r, "sync_minimum_time_interval");
      } else {
        Ignore(r, "read by the synchronous node only (sync and offline launch)");
      }
      return true;
    }
    if (key == "transform_timeout") {
      MapperParams probe;
      AssignFromString(probe, "sync_minimum_time_interval", text);
      transform_timeout_ = probe.sync_minimum_time_interval;
      transform_timeout_key_ = report_.keys.size();
      Ignore(r, "");
      return true;
    }
    if (key == "throttle_scans" && !sync) {
      AssignFromString(copy_, key, text);
      Ignore(r, "read by the synchronous node only (sync and offline launch)");
      return true;
    }
    if (const char* fallback = CeresFallback(key)) {
      std::string name = text;
      if (key == "ceres_trust_strategy" && text == "LM") name = fallback;  // its declared default
      if (!NamesAChoice(key, name)) {
        name = fallback;
        r.note = fmt::format("'{}' is not a value slam_toolbox knows: the node uses {}", text, fallback);
        Warn(r);
      }
      AssignFromString(copy_, key, name);
      Apply(r, key);
      return true;
    }
    if (const char* why = NotModelledToolboxKey(key, text)) {
      r.use = KeyUse::kNotModelled;
      r.note = why;
      Warn(r);
      report_.ignored.push_back(key);
      return true;
    }
    return false;
  }

  // slam_karto's own readings of a key; false for keys read as everywhere else.
  bool ReadKartoKey(KeyReport& r, const std::string& text) {
    if (r.key != "minimum_time_interval") return false;
    MapperParams probe;
    AssignFromString(probe, "sync_minimum_time_interval", text);
    if (probe.sync_minimum_time_interval > 0.0) {
      Ignore(r, "slam_karto never stamps its scans, so a positive value changes nothing");
      return true;
    }
    r.use = KeyUse::kNotModelled;
    r.note = "slam_karto never stamps its scans, so a value <= 0 makes it map every scan; slamtune does not";
    Warn(r);
    report_.ignored.push_back(r.key);
    return true;
  }

  void ClassifyNodeKey(KeyReport& r, const std::string& text) {
    if (ros2_) {
      if (const char* why = NotModelledToolboxKey(r.key, text.empty() && r.key == "mode" ? "mapping" : text)) {
        r.use = KeyUse::kNotModelled;
        r.note = why;
        Warn(r);
        report_.ignored.push_back(r.key);
        return;
      }
    }
    Ignore(r, "");
  }

  void Apply(KeyReport& r, const std::string& engine_name) {
    r.use = KeyUse::kEngine;
    report_.applied.push_back(engine_name);
  }
  void Ignore(KeyReport& r, std::string note) {
    r.use = KeyUse::kNodeOnly;
    r.note = std::move(note);
    report_.ignored.push_back(r.key);
  }
  void Warn(const KeyReport& r) {
    report_.warnings.push_back(fmt::format("{}:{}: {}: {}", source_, r.line, r.key, r.note));
  }
  void Add(KeyReport r) { report_.keys.push_back(std::move(r)); }

  MapperParams& copy_;
  bool ros2_;
  const std::string& source_;
  UnknownChoices unknown_choices_;  // reported with the values out of range, after the last key
  ParamsYamlReport report_;
  bool has_minimum_time_interval_ = false;
  std::optional<double> transform_timeout_;
  std::size_t transform_timeout_key_ = 0;
};

}  // namespace

const char* NameOf(KeyUse use) {
  switch (use) {
    case KeyUse::kEngine: return "used by the engine";
    case KeyUse::kNodeOnly: return "node-only (no effect on the map)";
    case KeyUse::kNotModelled: return "not modelled";
  }
  SLAMTUNE_CHECK(false);
  return "";
}

ParamsYamlReport ApplyParamsYaml(MapperParams& params, const std::string& yaml_text, const std::string& source) {
  YAML::Node root;
  try {
    root = YAML::Load(yaml_text);
  } catch (const YAML::Exception& e) {
    throw InputError(source, e.mark.line >= 0 ? e.mark.line + 1 : 0, e.msg);
  }
  const ParamsSection section = FindParamsSection(root, source);
  const YAML::Node& map = section.map;
  MapperParams copy = params;
  SectionReader reader(copy, section.ros2, source);
  const bool have_resolution = map["resolution"].IsDefined();
  for (const auto& entry : map) {
    reader.Read(io::YamlScalarText(entry.first, source, "a parameter name"), entry.second, have_resolution);
  }
  ParamsYamlReport report = reader.Finish();
  try {
    copy.Validate(reader.unknown_choices());
  } catch (const InputError& e) {
    throw InputError(source, 0, e.message());
  }
  params = copy;
  return report;
}

ParamsYamlReport ApplyParamsYamlFile(MapperParams& params, const std::string& path) {
  return ApplyParamsYaml(params, ReadTextFile(path), path);
}

}  // namespace slamtune::slam
