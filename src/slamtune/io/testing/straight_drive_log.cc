#include "slamtune/io/testing/straight_drive_log.h"

namespace slamtune::io::testing {

LaserLog StraightDriveLog(const StraightDrive& drive) {
  LaserLog log;
  for (int k = 0; k < drive.odometry_records; ++k) {
    OdomRecord r;
    r.ipc_time = drive.start_s + 0.1 * k;
    r.pose = Pose2{0.05 * k, 0.0, 0.0};
    r.tv = 0.5;
    log.odometry.push_back(r);
  }
  for (int k = 0; k < drive.scans; ++k) {
    LaserScanRecord s;
    s.ipc_time = drive.start_s + 0.2 * k;
    s.robot_pose = s.laser_pose = Pose2{0.1 * k, 0.0, 0.0};
    log.scans.push_back(s);
  }
  return log;
}

}  // namespace slamtune::io::testing
