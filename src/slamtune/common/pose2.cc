#include "slamtune/common/pose2.h"

#include <fmt/format.h>

namespace slamtune {

std::string ToString(const Pose2& p) { return fmt::format("({:.6f}, {:.6f}, {:.6f})", p.x, p.y, p.theta); }

}  // namespace slamtune
