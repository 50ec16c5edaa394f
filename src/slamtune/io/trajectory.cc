#include "slamtune/io/trajectory.h"

#include <fmt/format.h>

#include <iterator>
#include <unordered_map>

#include "slamtune/common/atomic_file.h"
#include "slamtune/common/error.h"
#include "slamtune/io/line_reader.h"

namespace slamtune::io {
namespace {

constexpr const char* kTrajectoryColumns[] = {"timestamp", "x", "y", "theta"};
constexpr std::size_t kNumTrajectoryColumns = 4;

}  // namespace

std::vector<TimedPose> ReadTrajectory(const std::string& path) {
  LineReader reader(path);
  std::vector<TimedPose> poses;
  std::vector<std::string_view> fields;
  std::string_view line;
  std::unordered_map<double, std::pair<std::size_t, std::size_t>> first_at_time;  // time -> pose index, line
  while (reader.Next(&line)) {
    if (IsBlankOrComment(line)) continue;
    SplitFields(line, &fields);
    if (fields.size() != kNumTrajectoryColumns) {
      throw InputError(path, reader.line_number(),
                       "expected 4 columns (timestamp x y theta), found " + std::to_string(fields.size()) +
                           (reader.unterminated() ? " (truncated last line?)" : ""));
    }
    double v[kNumTrajectoryColumns];
    for (std::size_t i = 0; i < kNumTrajectoryColumns; ++i)
      v[i] = RequireFinite(reader, fields[i], i + 1, kTrajectoryColumns[i]);
    const TimedPose pose{v[0], Pose2{v[1], v[2], v[3]}};
    const auto [it, first] = first_at_time.try_emplace(pose.time, poses.size(), reader.line_number());
    if (!first) {
      const Pose2& earlier = poses[it->second.first].pose;
      if (earlier == pose.pose) continue;  // the same pose written twice: nothing is ambiguous
      throw InputError(path, reader.line_number(),
                       fmt::format("second pose for timestamp {} (line {} has {} {} {}, this line {} {} {}): a "
                                   "trajectory needs one pose per timestamp",
                                   fields[0], it->second.second, earlier.x, earlier.y, earlier.theta, pose.pose.x,
                                   pose.pose.y, pose.pose.theta));
    }
    poses.push_back(pose);
  }
  return poses;
}

void WriteTrajectory(const std::string& path, const std::vector<TimedPose>& poses) {
  std::string text = "# timestamp x y theta (s, m, m, rad)\n";
  for (const TimedPose& p : poses) {
    fmt::format_to(std::back_inserter(text), "{:.6f} {:.9g} {:.9g} {:.9g}\n", p.time, p.pose.x, p.pose.y, p.pose.theta);
  }
  WriteFileAtomically(path, text);
}

}  // namespace slamtune::io
