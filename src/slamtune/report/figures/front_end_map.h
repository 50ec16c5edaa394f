// The run's map with its front-end evidence drawn where it happened (slam/front_end_evidence.h),
// so a user sees at a glance which corridor or doorway broke the map, not only scan numbers:
// the path of the run (final poses) in blue, degenerate stretches (the scans saw one direction
// only) in orange, suspect stretches in magenta, breaks as red rings labelled with their log scan
// index, and a legend with the counts. The map is cropped to its known cells and scaled up to a
// readable size with square cells (INTER_NEAREST), as map_panels.h does.
#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "slamtune/io/map_image.h"
#include "slamtune/io/trajectory.h"
#include "slamtune/slam/front_end_evidence.h"

namespace slamtune::report {

struct FrontEndMapOptions {
  int min_side = 900;    // px: the map is enlarged by a whole factor until its longer side reaches this, >= 64
  int max_side = 2400;   // px: ... and shrunk when it exceeds this, >= min_side
  int crop_margin = 10;  // cells kept around the known area, in [0, 1000]

  void Validate() const;
};

// `trajectory` holds one pose per log scan (index = log scan index, as LogRunner::Trajectory
// and SlamRun::trajectory give it); steps whose log index it does not hold are not drawn.
// Throws InputError for a map without cells.
cv::Mat RenderFrontEndMap(const io::MapImage& map, const std::vector<io::TimedPose>& trajectory,
                          const std::vector<slam::SequentialMatchStep>& steps, const slam::FrontEndEvidence& evidence,
                          const FrontEndMapOptions& options = {});

}  // namespace slamtune::report
