// MCAP files (io/ros/mcap_reader.h), in memory, with the messages decoded.
#include <span>

#include "container_fuzz.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::span<const std::uint8_t> bytes(data, size);
  slamtune::fuzz::FuzzContainer([&](const auto& options, const auto& on_message) {
    slamtune::io::ReadMcapBytes(bytes, "fuzz.mcap", options, on_message);
  });
  return 0;
}
