// The container fuzz targets' common loop: read the bytes strictly and leniently, and decode
// every message of a laser scan, odometry or tf type the way a recording's reader would.
#pragma once

#include <functional>

#include "slamtune/common/error.h"
#include "slamtune/io/ros/recording_container.h"
#include "slamtune/io/ros/ros_messages.h"

namespace slamtune::fuzz {

using ContainerRead = std::function<void(const io::ContainerReadOptions&, const io::MessageCallback&)>;

inline void DecodeRecorded(const io::RecordedTopic& topic, const io::RecordedMessage& message) {
  try {
    switch (io::KindOfRosType(topic.type)) {
      case io::RosMessageKind::kLaserScan: io::DecodeLaserScan(message.data, topic.serialization); break;
      case io::RosMessageKind::kOdometry: io::DecodeOdometry(message.data, topic.serialization); break;
      case io::RosMessageKind::kTf: io::DecodeTfMessage(message.data, topic.serialization); break;
      case io::RosMessageKind::kOther: break;
    }
  } catch (const InputError&) {
  }
}

inline void FuzzContainer(const ContainerRead& read) {
  for (const bool lenient : {false, true}) {
    io::ContainerReadOptions options;
    options.lenient = lenient;
    try {
      read(options, DecodeRecorded);
    } catch (const InputError&) {
    }
  }
}

}  // namespace slamtune::fuzz
