// The answer of `slamtune optimize` as parameter files the robot's node loads as they are
// (slam/params/ros_node_files.h): for slam_toolbox (ROS 2) best.yaml (full) and best_change.yaml (only
// what differs from the base), for slam_karto (ROS 1) best_slam_karto.yaml and
// best_slam_karto_change.yaml. Each file's first comment line says whether the recommendation
// is better than the base; when it is not, the full file is the base unchanged and the change
// file holds no parameter; it also names the node and mode the engine modelled
// (slam::NodeMode). Each file is checked the way its node reads it before it is written.
#pragma once

#include <string>
#include <vector>

#include "slamtune/optim/optimize_result.h"
#include "slamtune/tune/tuning_inputs.h"

namespace slamtune::tune {

struct RecommendationFiles {
  std::vector<std::string> written;   // file names, in the folder
  std::vector<std::string> changes;   // "name: base -> tuned" (slam_toolbox's names)
  std::vector<std::string> warnings;  // e.g. the behaviour tuned with is not the node's
};

RecommendationFiles WriteRecommendationFiles(const std::string& dir, const TuningInputs& inputs,
                                             const slam::MapperParams& recommended,
                                             const optim::OptimizeResult& result);

// The lines that tell how to load the files (README, report, the end of `optimize`), with the
// launch file of the slam_toolbox mode tuned for (online_async_launch.py for slam_karto's).
std::vector<std::string> HowToLoad(const std::string& dir, slam::NodeMode mode);

// slam_toolbox's launch file for `mode`: online_async_launch.py, online_sync_launch.py or
// offline_launch.py (online_async_launch.py when the mode is slam_karto's).
const char* ToolboxLaunchFile(slam::NodeMode mode);

}  // namespace slamtune::tune
