#include "slamtune/tune/optimize/recommendation_files.h"

#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "slamtune/common/atomic_file.h"
#include "slamtune/common/error.h"
#include "slamtune/slam/log_runner.h"

namespace slamtune::tune {
namespace {

struct Target {
  slam::RosNode node;
  const char* full;
  const char* change;
  const char* behaviour;  // what the node's Karto does, to compare with the engine's
};

constexpr Target kTargets[] = {
    {slam::RosNode::kSlamToolbox, "best.yaml", "best_change.yaml", "a pose graph over robot poses (robot_pose_graph)"},
    {slam::RosNode::kSlamKarto, "best_slam_karto.yaml", "best_slam_karto_change.yaml",
     "a pose graph over sensor poses"},
};

// ROS-level values of the recording, for a file made from scratch.
std::map<std::string, std::string> RosLevel(const io::LaserLog& log) {
  std::map<std::string, std::string> out;
  if (!log.recording) return out;
  const io::RecordingInfo& r = *log.recording;
  if (!r.odom_frame.empty()) out["odom_frame"] = r.odom_frame;
  if (!r.base_frame.empty()) out["base_frame"] = r.base_frame;
  if (!r.scan_topic.empty()) out["scan_topic"] = r.scan_topic;
  return out;
}

// A warning when the laser is off the base and the engine's graph is not the node's.
std::string BehaviourWarning(const Target& target, const TuningInputs& inputs, const slam::MapperParams& params) {
  const slam::OdometryFrame frame = slam::OdometryFrameOf(*inputs.log);
  const bool offset = frame.robot_poses && frame.offset != Pose2{};
  const bool node_robot_graph = target.node == slam::RosNode::kSlamToolbox;
  if (!offset || params.robot_pose_graph == node_robot_graph) return "";
  return fmt::format(
      "the values were found with {} but {}'s Karto builds {}, and this robot's laser is {:.3f} m, "
      "{:.3f} m, {:.3f} rad off the base: for {} exactly, tune with {}",
      params.robot_pose_graph ? "a robot-pose graph (slam_toolbox)" : "a sensor-pose graph (slam_karto)",
      slam::RosNodeName(target.node), target.behaviour, frame.offset.x, frame.offset.y, frame.offset.theta,
      slam::RosNodeName(target.node),
      node_robot_graph ? "--preset slam_toolbox (or its --params file)" : "--preset slam_karto");
}

std::vector<std::string> Header(const Target& target, const TuningInputs& inputs, const optim::OptimizeResult& result,
                                const std::string& recommended_summary) {
  std::vector<std::string> lines;
  // "tuned for MODE" is read back by slam/params/base_configuration.h, so `run --params` runs that mode.
  const std::string tuned_for = fmt::format("slamtune optimize, tuned for {} ({})", slam::NameOf(inputs.base.node_mode),
                                            slam::LaunchOf(inputs.base.node_mode));
  if (result.verdict_kind == optim::VerdictKind::kBetter) {
    lines.push_back(fmt::format("{}: the recommendation ({}) gives a cleaner map than {} on {}", tuned_for,
                                recommended_summary, inputs.base_label, inputs.source.log_label));
  } else {
    lines.push_back(
        fmt::format("{}: NOT better than {} ({}: {}); keep your values — this file is {} "
                    "unchanged and the change file is empty",
                    tuned_for, inputs.base_label, optim::VerdictKindName(result.verdict_kind), recommended_summary,
                    inputs.base_label));
  }
  if (target.node == slam::RosNode::kSlamToolbox) {
    lines.push_back(fmt::format("slam_toolbox (ROS 2): ros2 launch slam_toolbox {} slam_params_file:={}",
                                ToolboxLaunchFile(inputs.base.node_mode), target.full));
  } else {
    lines.push_back(
        fmt::format("slam_karto (ROS 1): rosparam load {} /slam_karto, or <rosparam file=\"{}\"/> in the "
                    "slam_karto node of the launch file",
                    target.full, target.full));
    lines.push_back(
        "loop_match_maximum_variance_coarse, distance_variance_penalty and angle_variance_penalty are "
        "written as slam_karto passes them to Karto, which squares them (0.4 means 0.16 m^2)");
  }
  return lines;
}

std::string Summary(const optim::OptimizeResult& result) {
  const auto* best = result.Find("recommended");
  std::string out;
  for (const auto& [name, value] : best->record.params)
    out += fmt::format("{}{} {}", out.empty() ? "" : ", ", name, value);
  return out;
}

}  // namespace

RecommendationFiles WriteRecommendationFiles(const std::string& dir, const TuningInputs& inputs,
                                             const slam::MapperParams& recommended,
                                             const optim::OptimizeResult& result) {
  RecommendationFiles out;
  const bool better = result.verdict_kind == optim::VerdictKind::kBetter;
  for (const Target& target : kTargets) {
    slam::NodeFileInputs in;
    in.base = inputs.base;
    in.tuned = better ? recommended : inputs.base;
    in.base_file_text = inputs.base_file_text;
    in.ros_level = RosLevel(*inputs.log);
    in.comments = Header(target, inputs, result, Summary(result));
    if (const std::string warning = BehaviourWarning(target, inputs, recommended); !warning.empty()) {
      in.comments.push_back("warning: " + warning);
      out.warnings.push_back(fmt::format("{}: {}", target.full, warning));
    }
    slam::NodeFiles files = slam::MakeNodeFiles(target.node, in, better);
    if (!files.not_written.empty()) {
      std::string names;
      for (const std::string& n : files.not_written) names += (names.empty() ? "" : ", ") + n;
      const std::string note =
          fmt::format("{} has no parameter for {}: the node keeps its own", slam::RosNodeName(target.node), names);
      files.full = "# note: " + note + "\n" + files.full;
      out.warnings.push_back(fmt::format("{}: {}", target.full, note));
    }
    // What the node would object to in the user's own file stays theirs (and is said); anything
    // else is a bug of the writer.
    std::vector<std::string> known;
    if (!inputs.base_file_text.empty() && inputs.base_node == target.node) {
      known = slam::CheckNodeFile(target.node, inputs.base_file_text);
      for (const std::string& problem : known) {
        out.warnings.push_back(fmt::format("{} (kept from your file): {}", target.full, problem));
      }
    }
    for (const std::string* text : {&files.full, &files.change}) {
      for (const std::string& problem : slam::CheckNodeFile(target.node, *text)) {
        const bool theirs = std::find(known.begin(), known.end(), problem) != known.end();
        SLAMTUNE_CHECK_MSG(theirs, fmt::format("{} would not load: {}", target.full, problem));
      }
    }
    WriteFileAtomically((std::filesystem::path(dir) / target.full).string(), files.full);
    WriteFileAtomically((std::filesystem::path(dir) / target.change).string(), files.change);
    out.written.insert(out.written.end(), {target.full, target.change});
    if (target.node == slam::RosNode::kSlamToolbox) out.changes = files.changed;
  }
  return out;
}

const char* ToolboxLaunchFile(slam::NodeMode mode) {
  switch (mode) {
    case slam::NodeMode::kSlamToolboxSync: return "online_sync_launch.py";
    case slam::NodeMode::kSlamToolboxOffline: return "offline_launch.py";
    case slam::NodeMode::kSlamKarto:
    case slam::NodeMode::kSlamToolboxAsync: return "online_async_launch.py";
  }
  return "online_async_launch.py";
}

std::vector<std::string> HowToLoad(const std::string& dir, slam::NodeMode mode) {
  const std::string d = std::filesystem::absolute(dir).string();
  return {
      fmt::format("slam_toolbox (ROS 2): ros2 launch slam_toolbox {} slam_params_file:={}/best.yaml",
                  ToolboxLaunchFile(mode), d),
      fmt::format("  or merge {}/best_change.yaml into your own file", d),
      fmt::format("slam_karto (ROS 1):   rosparam load {}/best_slam_karto.yaml /slam_karto  (before starting it)", d)};
}

}  // namespace slamtune::tune
