// rosbag2 SQLite3 databases (io/ros/rosbag2_sqlite_reader.h), as a database image in memory, with
// the messages decoded.
#include <vector>

#include "container_fuzz.h"
#include "slamtune/io/ros/ros_recording.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  slamtune::fuzz::FuzzContainer([&](const auto& options, const auto& on_message) {
    slamtune::io::ReadContainerBytes(slamtune::io::ContainerFormat::kRosbag2Sqlite,
                                     std::vector<std::uint8_t>(data, data + size), "fuzz.db3", options, on_message);
  });
  return 0;
}
