// Test helper: odometry faults written in one call.
#pragma once

#include "slamtune/sim/odometry_fault.h"

namespace slamtune::sim::testing {

// A fault of `kind` over [start_m, start_m + length_m] of the odometric travel.
inline OdometryFault Fault(OdometryFaultKind kind, double start_m, double length_m, double magnitude = 0.0) {
  OdometryFault fault;
  fault.kind = kind;
  fault.start_m = start_m;
  fault.length_m = length_m;
  fault.magnitude = magnitude;
  return fault;
}

}  // namespace slamtune::sim::testing
