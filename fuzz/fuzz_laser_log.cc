// A whole recording read as a laser log, as every command reads its LOG (io/log_reader.h): the
// format judged by content (MCAP, rosbag2 SQLite, ROS 1 bag, zstd-compressed split, CARMEN), the
// scans, odometry and tf assembled into poses and one beam geometry, strict and lenient.
#include "fuzz_files.h"
#include "slamtune/common/error.h"
#include "slamtune/io/log_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = slamtune::fuzz::WriteTempFile("recording", slamtune::fuzz::AsText(data, size));
  for (const bool lenient : {false, true}) {
    slamtune::io::LogReadOptions options;
    options.lenient = lenient;
    try {
      slamtune::io::ReadLaserLog(path, options);
    } catch (const slamtune::InputError&) {
    }
  }
  return 0;
}
