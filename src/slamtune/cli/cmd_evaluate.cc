// `slamtune evaluate MAP [MAP...]`: the map-quality figures (metrics/map_quality.h) of saved
// maps, from this engine or any SLAM system that writes map_server PGM/YAML or PNG
// (tune/map_evaluation.h), as a table or JSON.
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "slamtune/cli/command_registry.h"
#include "slamtune/tune/map_evaluation.h"

namespace slamtune::cli {
namespace {

struct EvaluateArgs {
  std::vector<std::string> maps;
  bool json = false;
  std::string debug_dir;  // empty: no overlays
  metrics::MapQualityOptions options;
};

void PrintTable(const std::vector<tune::MapEvaluation>& rows) {
  std::size_t name_width = 3;
  for (const tune::MapEvaluation& row : rows) name_width = std::max(name_width, row.map.size());
  std::printf("%s\n", fmt::format("{:<{}}  {:>11}  {:>9}  {:>9}  {:>11}  {:>7}  {:>8}  {:>8}", "map", name_width,
                                  "size", "eta", "eta_known", "corner_px", "corners", "enclosed", "contours")
                          .c_str());
  for (const tune::MapEvaluation& row : rows) {
    const metrics::MapQuality& q = row.quality;
    std::printf("%s\n", fmt::format("{:<{}}  {:>11}  {:>9.6f}  {:>9.6f}  {:>11}  {:>7}  {:>8}  {:>8}", row.map,
                                    name_width, fmt::format("{}x{}", q.width, q.height), q.occupied_ratio,
                                    q.occupied_ratio_known, q.corner_pixels, q.corners, q.enclosed_areas, q.contours)
                            .c_str());
  }
  std::printf("eta = occupied/all cells, n_c = corner_px (Harris pixels), n_e = enclosed; lower is better\n");
}

int Run(const EvaluateArgs& args) {
  const std::vector<tune::MapEvaluation> rows = tune::EvaluateMaps(args.maps, args.options, args.debug_dir);
  if (args.json) {
    nlohmann::ordered_json list = nlohmann::ordered_json::array();
    for (const tune::MapEvaluation& row : rows) list.push_back(tune::ToJson(row));
    std::printf("%s\n", list.dump(2).c_str());
  } else {
    PrintTable(rows);
  }
  return 0;
}

const SubcommandRegistrar kEvaluate(Subcommand{
    "evaluate",
    "Map-quality figures of saved maps (map_server YAML, PGM or PNG): occupied-cell ratio (eta), Harris corner "
    "pixels (n_c) and enclosed areas (n_e); lower is better",
    40, [](CLI::App& app) -> std::function<int()> {
      auto args = std::make_shared<EvaluateArgs>();
      metrics::MapQualityOptions& o = args->options;
      app.add_option("MAP", args->maps, "Map files: map_server .yaml (with its image), or a .pgm / .png alone")
          ->required();
      app.add_flag("--json", args->json, "Print a JSON list, one object per map");
      app.add_option("--debug-dir", args->debug_dir,
                     "Write an overlay PNG per map here (enclosed areas filled, corners in red)");
      app.add_option("--blur-size", o.blur_size, "Gaussian kernel side before Harris, px, odd")->capture_default_str();
      app.add_option("--blur-sigma", o.blur_sigma, "Gaussian sigma, px (0 = from the kernel size)")
          ->capture_default_str();
      app.add_option("--harris-block-size", o.harris_block_size, "Harris window, px")->capture_default_str();
      app.add_option("--harris-aperture", o.harris_aperture, "Sobel aperture: 1, 3, 5 or 7")->capture_default_str();
      app.add_option("--harris-k", o.harris_k, "Harris k in (0, 0.25)")->capture_default_str();
      app.add_option("--corner-threshold", o.corner_threshold,
                     "Corner pixel: response > this fraction of the map's largest response")
          ->capture_default_str();
      app.footer(
          "Examples:\n"
          "  slamtune evaluate map.yaml\n"
          "  slamtune evaluate runs/a/map.yaml runs/b/map.yaml --json\n"
          "  slamtune evaluate map.pgm --debug-dir overlays/");
      return [args]() -> int { return Run(*args); };
    }});

}  // namespace
}  // namespace slamtune::cli
