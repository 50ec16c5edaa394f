// Planted odometry failures in a recorded log (`slamtune fault`): the faults of odometry_fault.h
// (spin, jump, reverse), with the same meaning as in the simulator, put into a real recording, so
// that a tuner's repair of a broken front end can be measured on real scans, where the log's own
// Freiburg relations still give the error.
//
// A real log has no true trajectory, so a fault is located by the log's own odometric travel: the
// sum of the distances between consecutive odometric robot poses. Those poses are every ODOM
// record's and every scan's robot pose, taken together in file order (a CARMEN log: the order the
// logger wrote them, which its timestamps do not always follow) or, for a ROS recording, in time
// order (odometry first at equal times). Each step between two consecutive poses is the increment
// the odometry reported, in the frame of the first; a fault changes the steps its stretch
// overlaps, in proportion to the overlap (FaultEffectOnStep):
//
//   spin     MAGNITUDE rad of extra rotation are added to the steps' rotation;
//   jump     MAGNITUDE m of extra travel are added along each step's direction of travel;
//   reverse  each step's translation over the stretch is reported with its sign flipped.
//
// The changed steps are composed again from the last unchanged pose, so every pose after the
// stretch is the original pose moved by one rigid transform: the displacement the fault leaves.
// Poses before the first fault are kept bit for bit, poses after a fault are that transform
// composed with the original; laser poses follow their robot poses (laser = robot (+) the scan's
// mounting offset). Readings, timestamps, beam geometry and every other field are unchanged, and
// so are the ODOM records' velocities: a fault is in the integrated odometry only.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/common/pose2.h"
#include "slamtune/io/laser_log.h"
#include "slamtune/sim/odometry_fault.h"

namespace slamtune::sim {

// Where one planted fault fell in the log.
struct PlantedLogFault {
  OdometryFault fault;
  // The first scan (index into log.scans) whose robot pose the fault changed and its time in
  // seconds since the log's first scan (as `slamtune run` gives the front end's evidence); none
  // when no scan follows the fault's start.
  std::optional<std::size_t> first_scan;
  double first_time = 0.0;
  std::size_t scans_within = 0;  // scans whose odometric travel lies in (start_m, start_m + length_m]
  // The rigid transform that maps every original pose after the stretch (and before the next
  // fault) onto its faulted pose, faulted = displacement (+) original; it holds the faults
  // before this one too.
  Pose2 displacement;
  // How far the odometry at the end of the stretch is from where it was (m), and its heading change (rad).
  double shift_m = 0.0;
  double turn_rad = 0.0;

  // "reverse at 250 m over 3 m: travel reported backwards: from scan 6758 (1335.5 s into the
  // log), 79 scans within; odometry after it 5.151 m and 0.0 deg off".
  std::string Describe() const;
};

struct LogFaultSummary {
  double travel_m = 0.0;                // odometric travel of the whole log (m)
  std::size_t poses = 0;                // robot poses on the odometric path (ODOM records + scans)
  std::string order;                    // "file order" or "time order"
  std::vector<PlantedLogFault> faults;  // in the order given
};

// Plants `faults` into `log` (in place) and says where they fell. Throws InputError, before
// changing anything, when a fault is invalid (OdometryFault::Validate), when the log has fewer
// than two robot poses, or when a stretch does not end within the log's odometric travel; the
// message names the fault as given and the travel. Faults may overlap; their effects add.
LogFaultSummary PlantLogFaults(io::LaserLog& log, const std::vector<OdometryFault>& faults);

}  // namespace slamtune::sim
