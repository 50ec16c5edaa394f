// The transform tree of a recording, from its /tf and /tf_static messages, as tf2 keeps it:
// each frame has one parent; static transforms hold at all times, dynamic ones are looked up
// at a time by interpolating between the two samples around it (translation linearly,
// rotation by slerp; tf2's BufferCore does the same) and never extrapolated.
//
// Lookup(target, source, t) gives the pose of `source` in `target` (tf2's lookupTransform
// (target, source, t)), composed along the tree through the frames' common ancestor. A
// lookup fails — with the reason — when a frame is unknown, the frames are not connected, t
// lies outside a dynamic edge's samples, or the two samples around t are farther apart than
// the given maximum gap (a hole in the recording is not bridged). A sample exactly at t is returned as
// recorded.
//
// A loop — a frame that is its own ancestor, e.g. odom -> base_link -> laser -> odom, when a
// transform was published the wrong way round — makes tf2 refuse every lookup through it
// ("the tf tree is invalid because it contains a loop"): Loops() names them, and the recording
// reader refuses a recording whose odometry or laser offset would pass through one. A transform
// from a frame to itself, or with an empty frame id, is refused at Add as tf2 refuses it.
//
// Projection to the plane (ToPose2): x, y and the yaw of the rotation's Z-Y-X Euler angles
// (tf2::getYaw); the z axis of the rotated frame tells an upside-down sensor (z down).
#pragma once

#include <Eigen/Geometry>
#include <cstddef>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "slamtune/common/pose2.h"

namespace slamtune::io {

struct RigidTransform3 {
  Eigen::Vector3d translation = Eigen::Vector3d::Zero();
  Eigen::Quaterniond rotation = Eigen::Quaterniond::Identity();

  RigidTransform3 operator*(const RigidTransform3& other) const;  // this then other (child of this)
  RigidTransform3 Inverse() const;
};

// x, y and yaw (Z-Y-X Euler) of `t`.
Pose2 ToPose2(const RigidTransform3& t);
// Yaw about z of a quaternion, as tf2::getYaw: atan2(2(wz + xy), 1 - 2(y^2 + z^2)).
double YawOf(const Eigen::Quaterniond& q);

// A stamp in nanoseconds as messages about the recording give it, in seconds: "12.345678 s".
std::string StampText(std::int64_t stamp_ns);

// A frame id as tf2 names it: without the leading '/' ROS 1's tf allowed ("/base_link").
std::string NormalizeFrameId(const std::string& frame);

struct TfLookup {
  std::optional<RigidTransform3> transform;
  std::string failure;  // why not, when transform is empty
};

class TfBuffer {
 public:
  // Adds parent -> child at `stamp_ns`. Returns false (and counts a conflict) when `child`
  // already has another parent: tf2 keeps one parent per frame; the first one stays. A
  // transform whose parent is its child, or with an empty frame id, is refused (false, counted
  // in refused_frames).
  // A rotation is normalised; one whose squared norm is more than 0.01 from 1, or a non-finite
  // value, is refused as tf2 refuses it (false, counted in bad_rotations).
  // `received_ns` is when the recording received it (its log time), for lateness checks.
  bool Add(const std::string& parent, const std::string& child, std::int64_t stamp_ns, const RigidTransform3& t,
           bool is_static, std::int64_t received_ns = 0);

  // Dynamic samples farther apart than `max_gap_s` around the stamp are not interpolated.
  TfLookup Lookup(const std::string& target, const std::string& source, std::int64_t stamp_ns,
                  double max_gap_s = 0.5) const;
  // Whether `frame` is a parent or child of any transform.
  bool HasFrame(const std::string& frame) const;
  // Frames on the path from `frame` up to its root, `frame` first (up to the first frame seen
  // twice when the path runs into a loop).
  std::vector<std::string> PathToRoot(const std::string& frame) const;
  // The loop the path from `frame` up the tree runs into, as its transforms go, parent first and
  // the first frame again last ("odom", "base_link", "laser", "odom": odom is base_link's parent,
  // ..., laser is odom's); empty when the path ends at a root.
  std::vector<std::string> LoopAbove(const std::string& frame) const;
  // Every loop of the tree, each as LoopAbove gives it starting at its smallest frame name, in
  // name order.
  std::vector<std::vector<std::string>> Loops() const;
  // "a -> b (static), b -> c (dynamic, 812 samples)" per edge, for reports.
  std::vector<std::string> Describe() const;
  // The dynamic samples' stamps of the edge parent -> child (empty if none or static), and
  // when each was received, in stamp order.
  std::vector<std::int64_t> SampleStamps(const std::string& child) const;
  std::vector<std::int64_t> SampleReceiveTimes(const std::string& child) const;
  bool IsStatic(const std::string& child) const;
  std::string ParentOf(const std::string& child) const;  // "" for a root or unknown frame

  std::size_t parent_conflicts() const { return parent_conflicts_; }
  std::size_t bad_rotations() const { return bad_rotations_; }
  std::size_t refused_frames() const { return refused_frames_; }
  std::size_t transforms() const { return transforms_; }

 private:
  struct Sample {
    std::int64_t stamp_ns;
    RigidTransform3 transform;
    std::int64_t received_ns;
  };
  struct Edge {
    std::string parent;
    bool is_static = false;
    std::vector<Sample> samples;  // by stamp (static: the last one received)
    bool sorted = true;
  };
  // The child's transform in its parent at `stamp_ns`, or the reason it has none.
  TfLookup EdgeAt(const std::string& child, const Edge& edge, std::int64_t stamp_ns, std::int64_t max_gap_ns) const;
  void SortEdges() const;

  mutable std::map<std::string, Edge> edges_;  // by child frame
  std::size_t parent_conflicts_ = 0;
  std::size_t bad_rotations_ = 0;
  std::size_t refused_frames_ = 0;
  std::size_t transforms_ = 0;
};

}  // namespace slamtune::io
