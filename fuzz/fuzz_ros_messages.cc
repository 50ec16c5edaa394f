// The LaserScan, Odometry and TFMessage decoders (io/ros/ros_messages.h): every input is decoded as
// each type in both serializations.
#include <span>

#include "slamtune/common/error.h"
#include "slamtune/io/ros/ros_messages.h"

namespace {

template <typename Decode>
void Try(Decode decode) {
  try {
    decode();
  } catch (const slamtune::InputError&) {
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using slamtune::io::MessageSerialization;
  const std::span<const std::uint8_t> bytes(data, size);
  for (const auto serialization : {MessageSerialization::kCdr, MessageSerialization::kRos1}) {
    Try([&] { slamtune::io::DecodeLaserScan(bytes, serialization); });
    Try([&] { slamtune::io::DecodeOdometry(bytes, serialization); });
    Try([&] { slamtune::io::DecodeTfMessage(bytes, serialization); });
  }
  return 0;
}
