#include "slamtune/io/ros/recording_container.h"

namespace slamtune::io {

std::string MessageLocation::ToString() const {
  return (kind == Kind::kRow ? "row " : "byte ") + std::to_string(value);
}

}  // namespace slamtune::io
