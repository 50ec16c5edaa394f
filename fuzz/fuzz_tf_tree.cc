// The transform tree of a recording (io/ros/tf_buffer.h), built from the input as a program: each
// step adds a transform (static or dynamic, with any stamp, translation and rotation, NaN and
// infinities included, between frames of a small set that makes loops, second parents and
// self-transforms likely) or asks the tree something. Besides crashes, the tree's promises are
// checked: a path up the tree never repeats a frame and follows ParentOf, every loop named
// closes on its first frame and follows ParentOf, and a transform found has a unit rotation.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz_input.h"
#include "slamtune/common/error.h"
#include "slamtune/io/ros/tf_buffer.h"

namespace {

using slamtune::io::RigidTransform3;
using slamtune::io::TfBuffer;

const std::vector<std::string> kFrames = {"odom", "base_link", "base_footprint", "laser", "map", "camera", "", "a"};

RigidTransform3 Transform(slamtune::fuzz::FuzzInput& in) {
  RigidTransform3 t;
  t.translation = {in.Double(), in.Double(), in.Double()};
  if (in.Bool()) {
    t.rotation = Eigen::Quaterniond(Eigen::AngleAxisd(in.Double(), Eigen::Vector3d::UnitZ()));
  } else {
    t.rotation = Eigen::Quaterniond(in.Double(), in.Double(), in.Double(), in.Double());  // any norm
  }
  return t;
}

void CheckLoop(const TfBuffer& tf, const std::vector<std::string>& loop) {
  if (loop.empty()) return;
  SLAMTUNE_CHECK(loop.size() >= 3 && loop.front() == loop.back());
  for (std::size_t k = 1; k < loop.size(); ++k) SLAMTUNE_CHECK(tf.ParentOf(loop[k]) == loop[k - 1]);
  for (std::size_t k = 0; k + 1 < loop.size(); ++k) {
    for (std::size_t j = k + 1; j + 1 < loop.size(); ++j) SLAMTUNE_CHECK(loop[k] != loop[j]);
  }
}

void CheckPath(const TfBuffer& tf, const std::vector<std::string>& path) {
  for (std::size_t k = 1; k < path.size(); ++k) {
    SLAMTUNE_CHECK(tf.ParentOf(path[k - 1]) == path[k]);
    for (std::size_t j = 0; j < k; ++j) SLAMTUNE_CHECK(path[j] != path[k]);
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  slamtune::fuzz::FuzzInput in(data, size);
  TfBuffer tf;
  constexpr std::int64_t kTick = 10000000;  // stamps in steps of 10 ms
  for (int step = 0; step < 256 && !in.empty(); ++step) {
    switch (in.Byte() % 8) {
      case 0:
      case 1:
      case 2:
      case 3: {
        const std::string& parent = in.Name(kFrames);
        const std::string& child = in.Name(kFrames);
        const std::int64_t stamp = in.Stamp(kTick);
        const bool is_static = in.Bool();
        tf.Add(parent, child, stamp, Transform(in), is_static, in.Stamp(kTick));
        break;
      }
      case 4: {
        const std::string& target = in.Name(kFrames);
        const std::string& source = in.Name(kFrames);
        const std::int64_t stamp = in.Stamp(kTick);
        const double gap = in.Double();
        const slamtune::io::TfLookup found = tf.Lookup(target, source, stamp, std::isfinite(gap) ? gap : 0.5);
        if (found.transform) {
          SLAMTUNE_CHECK(std::fabs(found.transform->rotation.norm() - 1.0) < 1e-6);
          slamtune::io::ToPose2(*found.transform);
        } else {
          SLAMTUNE_CHECK(!found.failure.empty());
        }
        break;
      }
      case 5: {
        const std::string& frame = in.Name(kFrames);
        CheckLoop(tf, tf.LoopAbove(frame));
        CheckPath(tf, tf.PathToRoot(frame));
        break;
      }
      case 6:
        for (const std::vector<std::string>& loop : tf.Loops()) CheckLoop(tf, loop);
        tf.Describe();
        break;
      default: {
        const std::string& frame = in.Name(kFrames);
        SLAMTUNE_CHECK(tf.SampleStamps(frame).size() == tf.SampleReceiveTimes(frame).size());
        tf.IsStatic(frame);
        tf.HasFrame(frame);
        break;
      }
    }
  }
  return 0;
}
