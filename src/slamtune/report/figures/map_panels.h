// Occupancy maps as labelled figure panels, for the report's side-by-side comparison of the
// candidates' maps.
//
// A SLAM map is mostly unknown border, so each map is first cropped to its known cells (plus
// a margin) and then scaled to a common height, so maps of different extents compare at a
// glance; INTER_AREA when shrinking keeps one-cell walls visible as grey rather than dropping
// them, INTER_NEAREST when enlarging keeps cells square. The greys are map_server's
// (occupied black, free near-white, unknown grey, io/map_image.h).
#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "slamtune/io/map_image.h"

namespace slamtune::report {

struct MapPanelOptions {
  int height = 480;         // px, height of the map part of every panel, in [32, 4000]
  int max_width = 1200;     // px, wider maps are shrunk to this width (keeping the aspect), >= 32
  bool crop = true;         // crop each map to its known (non-unknown) cells first
  int crop_margin = 10;     // cells of border kept around the known area, in [0, 1000]
  double font_scale = 0.6;  // Hershey simplex scale of the label (caption 0.85x), in (0, 4]
  bool scale_bar = true;    // a bar of a round length (1, 2 or 5 times a power of ten metres) under the map

  void Validate() const;
};

// True when the map has cells and width * height pixels (what WriteMapServer accepts).
bool HasMap(const io::MapImage& map);

// Bounding box (in image pixels) of the cells that are not unknown, grown by `margin` and
// kept inside the image; the whole image when every cell is unknown.
cv::Rect KnownBounds(const io::MapImage& map, int margin);

// A segment in the map's world frame (m), e.g. a loop closure from an earlier robot pose
// (x0, y0) to the pose that closed it (x1, y1), with a short label at its closing end.
struct MapSegment {
  double x0 = 0.0, y0 = 0.0, x1 = 0.0, y1 = 0.0;
  std::string label;
};

// What is drawn over a map: a path (world m, e.g. the robot's trajectory, thin sky blue) and
// segments (vermillion: a line, a dot at the start, a ring and the label at the end).
struct MapOverlay {
  std::vector<cv::Point2d> path;
  std::vector<MapSegment> segments;
};

// The round length (1, 2 or 5 times a power of ten, m) of a scale bar for a map drawn
// `px_per_m` pixels per metre and `width_px` wide: the largest not longer than a quarter of
// the width. px_per_m > 0, width_px > 0.
double ScaleBarLength(double px_per_m, int width_px);

// A BGR panel: `label` on top, the map (cropped and scaled) under it with `overlay` drawn
// over it, a scale bar under the map (options.scale_bar), `caption` below, wrapped to the
// map's width. A map without cells (HasMap false) gives a grey placeholder saying so, of the
// same height.
cv::Mat RenderMapPanel(const io::MapImage& map, const std::string& label, const std::string& caption,
                       const MapPanelOptions& options, const MapOverlay& overlay = {});

}  // namespace slamtune::report
