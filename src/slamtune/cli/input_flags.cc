#include "slamtune/cli/input_flags.h"

namespace slamtune::cli {

void AddLogInputFlags(CLI::App& app, tune::LogInputOptions& options, MaxScansFlag max_scans) {
  app.add_flag("--lenient", options.lenient,
               "Skip malformed records or messages (and count them) instead of failing; a recording cut off inside "
               "a record reads up to its last whole record without it");
  app.add_option("--no-return", options.no_return,
                 "Readings >= this value (m) are no-returns; overrides the log's own (PARAM, range_max, detected)");
  if (max_scans == MaxScansFlag::kOffer) {
    app.add_option("--max-scans", options.max_scans, "Read only the first N laser scans (0 = all)");
  }
  app.add_option("--beams", options.beams,
                 "scans whose beam count changes: node (default: dropped, as the ROS node drops them), per-geometry "
                 "(one Karto laser per beam geometry) or nearest-beam (resampled onto the most common geometry, an "
                 "approximation)")
      ->capture_default_str();
  auto* ros = "ROS recordings";
  app.add_option("--scan-topic", options.scan_topic, "sensor_msgs/LaserScan topic (default: the only one)")->group(ros);
  app.add_option("--odom-topic", options.odom_topic,
                 "nav_msgs/Odometry topic for the robot poses (default: odom -> base frame from /tf)")
      ->group(ros);
  app.add_option("--odom-frame", options.odom_frame, "odometry frame of /tf (default: odom)")->group(ros);
  app.add_option("--base-frame", options.base_frame, "robot base frame (default: base_footprint, else base_link)")
      ->group(ros);
  app.add_option("--laser-offset", options.laser_offset,
                 "laser mounting pose in the base frame X,Y,YAW (m, m, rad), instead of the tf tree's")
      ->expected(3)
      ->delimiter(',')
      ->group(ros);
  app.add_option("--max-odom-gap", options.max_odom_gap_s, "odometry samples farther apart (s) are not interpolated")
      ->capture_default_str()
      ->group(ros);
}

void AddCarmenOutputFlags(CLI::App& app, std::string& out, bool& quiet, tune::LogInputOptions& input) {
  app.add_option("--out", out, "CARMEN log to write (.clf)")->required();
  app.add_flag("--quiet", quiet, "Do not print what was read");
  AddLogInputFlags(app, input);
}

void AddTuningInputFlags(CLI::App& app, tune::TuningInputOptions& options) {
  app.add_option("--relations", options.relations,
                 "Freiburg relations file: adds ground-truth errors to every evaluation");
  app.add_option("--world", options.world, "built-in world to simulate when no LOG is given (see `simulate --list`)")
      ->capture_default_str();
  app.add_option("--world-seed", options.world_seed, "seed of the simulated world")->capture_default_str();
  AddPresetFlag(app, options.preset);
  app.add_option("--params", options.params_file,
                 "your slam_toolbox (ROS 2) or slam_karto (ROS 1) parameter file: the base of every run and the "
                 "baseline; keys it does not set take that node's own defaults");
  app.add_option("--set", options.sets, "override one base parameter, NAME=VALUE (repeatable)");
  AddLogInputFlags(app, options.input);
}

CLI::Option* AddPresetFlag(CLI::App& app, std::string& preset) {
  return app.add_option("--preset", preset,
                        "the node and its defaults: slam_karto (default), open_karto, slam_toolbox (asynchronous "
                        "node), slam_toolbox_sync or slam_toolbox_offline (synchronous node, which filters scans); "
                        "with --params, only the node's mode: the file's keys go over that node's declared "
                        "defaults");
}

std::vector<CLI::Option*> AddParallelismFlags(CLI::App& app, tune::TuningRunOptions& run) {
  return {app.add_option("--jobs,-j", run.jobs,
                         "parallel SLAM runs (default: all cores; under mpirun: 1 on rank 0, each other rank runs "
                         "one)"),
          app.add_flag("--quiet,-q", run.quiet, "no progress output")};
}

std::vector<CLI::Option*> AddSharingFlags(CLI::App& app, tune::TuningRunOptions& run) {
  return {app.add_flag("--no-share", run.no_share,
                       "do not share scan matches, solves and map scores between SLAM runs (same results, slower; for "
                       "timing comparisons)"),
          app.add_option("--share-mb", run.share_mb,
                         "memory budget of the shared scan-match cache, MB (solves get half as much more, map scores "
                         "a quarter, barycentres an eighth)")
              ->capture_default_str()};
}

}  // namespace slamtune::cli
