// Test helper: the transforms of a robot on the floor, as the tf trees of most recordings hold.
#pragma once

#include <Eigen/Geometry>

#include "slamtune/io/ros/tf_buffer.h"

namespace slamtune::io::testing {

// Translation (x, y, z) and a rotation by `yaw` (rad) about z.
inline RigidTransform3 Planar(double x, double y, double yaw, double z = 0.0) {
  RigidTransform3 t;
  t.translation = {x, y, z};
  t.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()));
  return t;
}

}  // namespace slamtune::io::testing
