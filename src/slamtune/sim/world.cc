#include "slamtune/sim/world.h"

#include "slamtune/common/error.h"

namespace slamtune::sim {

void WallBuilder::Wall(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  SLAMTUNE_CHECK_MSG((b - a).norm() > 1e-9, "zero-length wall");
  walls_.push_back(Segment{a, b});
}

void WallBuilder::WallWithOpenings(const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                                   const std::vector<Opening>& openings) {
  const double length = (b - a).norm();
  SLAMTUNE_CHECK_MSG(length > 1e-9, "zero-length wall");
  const Eigen::Vector2d along = (b - a) / length;
  const Eigen::Vector2d left(-along.y(), along.x());
  double done = 0.0;  // distance along the wall already built
  for (const Opening& opening : openings) {
    const double begin = opening.at - opening.width / 2.0, end = opening.at + opening.width / 2.0;
    SLAMTUNE_CHECK_MSG(opening.width > 0.0 && begin >= done && end <= length, "openings overlap or leave the wall");
    if (begin > done) Wall(a + done * along, a + begin * along);
    if (opening.depth != 0.0) {
      const Eigen::Vector2d back = opening.depth * left;
      Wall(a + begin * along, a + begin * along + back);
      Wall(a + begin * along + back, a + end * along + back);
      Wall(a + end * along + back, a + end * along);
    }
    done = end;
  }
  if (done < length) Wall(a + done * along, b);
}

void WallBuilder::Box(const Eigen::Vector2d& min, const Eigen::Vector2d& max) {
  const Eigen::Vector2d c1(max.x(), min.y()), c2(min.x(), max.y());
  Wall(min, c1);
  Wall(c1, max);
  Wall(max, c2);
  Wall(c2, min);
}

}  // namespace slamtune::sim
