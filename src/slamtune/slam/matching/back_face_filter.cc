#include "slamtune/slam/matching/back_face_filter.h"

#include "slamtune/common/error.h"

namespace slamtune::slam {

void FilterBackFaces(std::span<const Eigen::Vector2d> points, const Eigen::Vector2d& viewpoint,
                     std::vector<Eigen::Vector2d>* valid) {
  SLAMTUNE_CHECK(valid != nullptr);
  valid->clear();
  ForEachValidPoint(points, viewpoint, [valid](const Eigen::Vector2d& p) { valid->push_back(p); });
}

std::vector<Eigen::Vector2d> FilterBackFaces(std::span<const Eigen::Vector2d> points,
                                             const Eigen::Vector2d& viewpoint) {
  std::vector<Eigen::Vector2d> valid;
  FilterBackFaces(points, viewpoint, &valid);
  return valid;
}

}  // namespace slamtune::slam
