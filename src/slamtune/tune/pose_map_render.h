// `slamtune render` as library work: the occupancy map of a log drawn from given poses (a
// simulated world's truth.txt, another system's trajectory, or the log's raw odometry;
// slam/pose_map.h), with its map metrics — e.g. to check that the metrics prefer the true map.
// The log and the base configuration (map resolution, laser range rules) are loaded as every
// command loads them (LoadTuningInputs). map.pgm, map.yaml and map.png are written whole or not at
// all (io/map_image.h).
#pragma once

#include <string>

#include "slamtune/metrics/map_quality.h"
#include "slamtune/slam/pose_map.h"
#include "slamtune/tune/tuning_inputs.h"

namespace slamtune::tune {

// The word of RenderOptions::poses that draws the log's own odometric poses.
inline constexpr const char* kOdometryPoses = "odometry";

struct RenderOptions {
  TuningInputOptions inputs;  // the log and the base configuration
  std::string poses;          // trajectory file (timestamp x y theta per scan), or kOdometryPoses
  std::string out;            // output folder (created)
};

struct RenderOutcome {
  slam::PoseMapSummary summary;  // scans drawn, and those without a pose
  int width = 0, height = 0;     // cells
  metrics::MapQuality quality;   // the map's figures (default options)
};

// Reads the trajectory, checks the output folder, loads the inputs (what was read on stderr),
// draws the map and writes map.pgm, map.yaml and map.png to options.out. InputError for an
// unreadable trajectory (before the log is read), an unwritable folder (before the log is read),
// a bad input or a trajectory with no pose at any scan.
RenderOutcome RenderAndWrite(const RenderOptions& options);

}  // namespace slamtune::tune
