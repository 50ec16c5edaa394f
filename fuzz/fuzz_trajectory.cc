// Trajectory files `timestamp x y theta` (io/trajectory.h), read from a file.
#include "fuzz_files.h"
#include "slamtune/common/error.h"
#include "slamtune/io/trajectory.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = slamtune::fuzz::WriteTempFile("trajectory.txt", slamtune::fuzz::AsText(data, size));
  try {
    slamtune::io::ReadTrajectory(path);
  } catch (const slamtune::InputError&) {
  }
  return 0;
}
