// Synthetic occupancy maps made of rectangular rooms, for known-answer tests of the
// map-quality metrics, the benchmark and the pictures in docs/metrics.md.
//
// A failed loop closure is imitated the way it looks in a real map: the same room drawn a
// second time, slightly rotated or shifted, so walls double and cross.
#pragma once

#include <vector>

#include "slamtune/io/map_image.h"

namespace slamtune::metrics {

// A rectangular room in image coordinates (column, row; row 0 at the top).
struct SyntheticRoom {
  double center_col = 0.0;  // cells
  double center_row = 0.0;  // cells
  double width = 0.0;       // cells, outer wall to outer wall along the room's own x axis; >= 3
  double height = 0.0;      // cells, likewise along its y axis; >= 3
  double angle_deg = 0.0;   // rotation about the centre, degrees (image axes)
};

// A width x height map, unknown everywhere except the rooms: every room's inside is free,
// then every room's outline is drawn as a 1-cell, 8-connected occupied wall (so a later room's
// free inside never erases an earlier room's wall). Resolution 0.05 m, origin 0.
// Throws InputError for a non-positive map size or a room smaller than 3 x 3 cells.
io::MapImage DrawSyntheticRooms(int width, int height, const std::vector<SyntheticRoom>& rooms);

}  // namespace slamtune::metrics
