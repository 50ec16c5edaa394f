#include "slamtune/io/trajectory.h"

#include <cerrno>
#include <cstdio>
#include <cstring>

#include "slamtune/common/error.h"
#include "slamtune/io/line_reader.h"

namespace slamtune::io {
namespace {

constexpr const char* kColumns[] = {"timestamp", "x", "y", "theta"};
constexpr std::size_t kNumColumns = 4;

}  // namespace

std::vector<TimedPose> ReadTrajectory(const std::string& path) {
  LineReader reader(path);
  std::vector<TimedPose> poses;
  std::vector<std::string_view> fields;
  std::string_view line;
  while (reader.Next(&line)) {
    if (IsBlankOrComment(line)) continue;
    SplitFields(line, &fields);
    if (fields.size() != kNumColumns) {
      throw InputError(path, reader.line_number(),
                       "expected 4 columns (timestamp x y theta), found " + std::to_string(fields.size()) +
                           (reader.unterminated() ? " (truncated last line?)" : ""));
    }
    double v[kNumColumns];
    for (std::size_t i = 0; i < kNumColumns; ++i) v[i] = RequireFinite(reader, fields[i], i + 1, kColumns[i]);
    poses.push_back(TimedPose{v[0], Pose2{v[1], v[2], v[3]}});
  }
  return poses;
}

void WriteTrajectory(const std::string& path, const std::vector<TimedPose>& poses) {
  std::FILE* file = std::fopen(path.c_str(), "w");
  if (file == nullptr) throw InputError(path, 0, std::string("cannot write: ") + std::strerror(errno));
  std::fprintf(file, "# timestamp x y theta (s, m, m, rad)\n");
  for (const TimedPose& p : poses) {
    std::fprintf(file, "%.6f %.9g %.9g %.9g\n", p.time, p.pose.x, p.pose.y, p.pose.theta);
  }
  const bool failed = std::ferror(file) != 0;
  if (std::fclose(file) != 0 || failed) throw InputError(path, 0, "cannot write: error while writing the file");
}

}  // namespace slamtune::io
