#include "slamtune/metrics/synthetic_map.h"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "slamtune/common/error.h"

namespace slamtune::metrics {
namespace {

// The four corners of a room, rounded to cells, in drawing order.
std::array<cv::Point, 4> Corners(const SyntheticRoom& room) {
  const double a = room.angle_deg * std::numbers::pi / 180.0;
  const double c = std::cos(a), s = std::sin(a);
  // Corner cells sit (size - 1) / 2 from the centre so an unrotated room of width w spans w cells.
  const double hx = (room.width - 1.0) / 2.0, hy = (room.height - 1.0) / 2.0;
  const std::array<std::array<double, 2>, 4> local = {{{-hx, -hy}, {hx, -hy}, {hx, hy}, {-hx, hy}}};
  std::array<cv::Point, 4> corners;
  for (int i = 0; i < 4; ++i) {
    const double x = room.center_col + c * local[i][0] - s * local[i][1];
    const double y = room.center_row + s * local[i][0] + c * local[i][1];
    corners[i] = cv::Point(static_cast<int>(std::lround(x)), static_cast<int>(std::lround(y)));
  }
  return corners;
}

}  // namespace

io::MapImage DrawSyntheticRooms(int width, int height, const std::vector<SyntheticRoom>& rooms) {
  if (width <= 0 || height <= 0) {
    throw InputError(fmt::format("synthetic map size {} x {}: both sides must be > 0 cells", width, height));
  }
  for (const SyntheticRoom& room : rooms) {
    if (!(room.width >= 3.0 && room.height >= 3.0)) {
      throw InputError(
          fmt::format("synthetic room {} x {} cells: both sides must be >= 3 cells (wall, "
                      "inside, wall)",
                      room.width, room.height));
    }
  }
  io::MapImage map = io::UniformMap(width, height, io::kMapUnknown);
  cv::Mat image(height, width, CV_8UC1, map.pixels.data());  // draws straight into the map
  for (const SyntheticRoom& room : rooms) {
    const auto corners = Corners(room);
    cv::fillConvexPoly(image, corners.data(), 4, cv::Scalar(io::kMapFree), cv::LINE_8);
  }
  for (const SyntheticRoom& room : rooms) {
    const auto corners = Corners(room);
    const cv::Point* outline = corners.data();
    const int count = 4;
    cv::polylines(image, &outline, &count, 1, /*isClosed=*/true, cv::Scalar(io::kMapOccupied), 1, cv::LINE_8);
  }
  return map;
}

}  // namespace slamtune::metrics
