#include "slamtune/optim/search_space.h"

#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <set>

#include "slamtune/common/error.h"
#include "slamtune/common/text_file.h"
#include "slamtune/io/yaml_text.h"

namespace slamtune::optim {
namespace {

double ReadNumber(const YAML::Node& node, const std::string& path, const std::string& what) {
  try {
    return node.as<double>();
  } catch (const YAML::Exception&) {
    throw InputError(path, node.Mark().line + 1, fmt::format("{} must be a number", what));
  }
}

// The table row of a parameter that can be searched: known and a number.
const slam::ParamInfo* NumericParam(const std::string& name, const std::string& path, std::size_t line) {
  const slam::ParamInfo* info = slam::FindParam(name);
  if (info == nullptr) throw InputError(path, line, slam::UnknownParamMessage(name));
  if (info->type != slam::ParamType::kInt && info->type != slam::ParamType::kDouble) {
    throw InputError(path, line,
                     fmt::format("'{}' is a {} parameter: only numbers can be searched (set it with fix: or --set)",
                                 name, slam::ParamTypeName(info->type)));
  }
  return info;
}

void SortRealsFirst(std::vector<Dimension>& dims) {
  std::stable_partition(dims.begin(), dims.end(), [](const Dimension& d) { return !d.integer; });
}

}  // namespace

double Dimension::ValueOf(double x) const {
  if (step > 0.0) {
    const double steps = std::floor((upper - lower) / step + 1e-9);
    const double k = std::clamp(std::round((x - lower) / step), 0.0, steps);
    // Nine decimals: 0.3 + 3 x 0.02 is 0.36, not 0.36000000000000004, so keys and files read as written.
    return std::round((lower + k * step) * 1e9) / 1e9;
  }
  return integer ? std::round(x) : x;
}

SearchSpace SearchSpace::PaperDefault() {
  SearchSpace s;
  s.dimensions = {{"loop_search_maximum_distance", 2.0, 6.0, false},
                  {"loop_match_minimum_chain_size", 6.0, 20.0, true}};
  s.fixed = {{"loop_match_minimum_response_coarse", 0.7}, {"loop_match_maximum_variance_coarse", 0.4}};
  return s;
}

SearchSpace SearchSpace::AroundBase(double base_r, int base_g) {
  SearchSpace s;
  s.dimensions = {{"loop_search_maximum_distance", std::min(2.0, base_r), std::max(6.0, base_r), false},
                  {"loop_match_minimum_chain_size", std::min(6.0, static_cast<double>(base_g)),
                   std::max(20.0, static_cast<double>(base_g)), true}};
  return s;
}

namespace {

// Whether a dimension is searched by real values or by whole numbers.
enum class Gene { kReal, kInteger };

// A range on a lattice through the base's value, reaching as close to [low, high] as the
// lattice allows and always holding the base: the baseline is a point of the space.
Dimension Around(const char* name, double base, double low, double high, double step, Gene gene = Gene::kReal) {
  const auto round9 = [](double v) { return std::round(v * 1e9) / 1e9; };
  const double down = base > low ? std::floor((base - low) / step + 1e-9) : 0.0;
  const double up = base < high ? std::floor((high - base) / step + 1e-9) : 0.0;
  return Dimension{name, round9(base - down * step), round9(base + up * step), gene == Gene::kInteger, step};
}

}  // namespace

SearchSpace SearchSpace::FrontEnd(const slam::MapperParams& base) {
  // The sequential search window must be an even number of cells (docs/engine.md §4.1):
  // its lattice is 2 x resolution through the base's (valid) window. 1.6 m at 1 cm is 161^2
  // cells per angle, ~28x the work of slam_karto's 0.3 m (31^2); docs/search-spaces.md.
  const double resolution = base.correlation_search_space_resolution;
  SearchSpace s;
  s.dimensions = {
      Around("correlation_search_space_dimension", base.correlation_search_space_dimension, 0.2, 1.6, 2.0 * resolution),
      // Karto accepts smearing in [0.5, 10] x resolution (§4.1).
      Around("correlation_search_space_smear_deviation", base.correlation_search_space_smear_deviation,
             3.0 * resolution, 10.0 * resolution, resolution / 2.0),
      // The heading range of the search (shared with the loop matcher, whose cost grows with it):
      // a spin the odometry missed by more than the range cannot be followed.
      Around("coarse_search_angle_offset", base.coarse_search_angle_offset, 0.2, 1.2, 0.01),
      Around("minimum_travel_distance", base.minimum_travel_distance, 0.1, 1.0, 0.01),
      Around("minimum_travel_heading", base.minimum_travel_heading, 0.1, 1.0, 0.01),
      Around("link_match_minimum_response_fine", base.link_match_minimum_response_fine, 0.05, 0.6, 0.01),
      Around("loop_search_maximum_distance", base.loop_search_maximum_distance, 2.0, 6.0, 0.01),
      Around("loop_match_minimum_response_coarse", base.loop_match_minimum_response_coarse, 0.3, 0.9, 0.01),
      Around("loop_match_maximum_variance_coarse", base.loop_match_maximum_variance_coarse, 0.1, 3.0, 0.01),
      Around("scan_buffer_size", base.scan_buffer_size, 5, 70, 1.0, Gene::kInteger),
      Around("loop_match_minimum_chain_size", base.loop_match_minimum_chain_size, 6, 20, 1.0, Gene::kInteger),
  };
  return s;
}

SearchSpace SearchSpace::Loop(const slam::MapperParams& base) {
  SearchSpace s;
  s.dimensions = {
      Around("loop_search_maximum_distance", base.loop_search_maximum_distance, 2.0, 6.0, 0.01),
      Around("loop_match_minimum_chain_size", base.loop_match_minimum_chain_size, 6, 20, 1.0, Gene::kInteger),
  };
  return s;
}

SearchSpace SearchSpace::FromYaml(const std::string& path) {
  const std::string text = ReadTextFile(path);  // a folder or unreadable path: InputError naming it
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::Exception& e) {
    throw InputError(path, e.mark.line + 1, fmt::format("not valid YAML: {}", e.msg));
  }
  if (!root.IsMap()) throw InputError(path, 0, "search space must be a map with keys 'vary' and 'fix'");
  SearchSpace s;
  for (const auto& top : root) {
    const std::string key = io::YamlScalarText(top.first, path, "a top-level key");
    if (key == "vary") {
      if (!top.second.IsMap()) throw InputError(path, top.second.Mark().line + 1, "'vary' must be a map");
      for (const auto& item : top.second) {
        Dimension d;
        d.name = io::YamlScalarText(item.first, path, "a parameter name");
        const std::size_t line = item.first.Mark().line + 1;
        s.lines[d.name] = line;
        const slam::ParamInfo* info = NumericParam(d.name, path, line);
        d.integer = info->type == slam::ParamType::kInt;
        const YAML::Node spec = item.second;
        if (!spec.IsMap() || !spec["min"] || !spec["max"]) {
          throw InputError(path, spec.Mark().line + 1,
                           fmt::format("'{}' needs {{min: LOW, max: HIGH[, type: int|real]}}", d.name));
        }
        for (const auto& field : spec) {
          const std::string f = io::YamlScalarText(field.first, path, "a key of '" + d.name + "'");
          if (f != "min" && f != "max" && f != "type" && f != "step") {
            throw InputError(path, field.first.Mark().line + 1,
                             fmt::format("'{}': unknown key '{}' (allowed: min, max, step, type)", d.name, f));
          }
        }
        d.lower = ReadNumber(spec["min"], path, d.name + ".min");
        d.upper = ReadNumber(spec["max"], path, d.name + ".max");
        if (spec["step"]) d.step = ReadNumber(spec["step"], path, d.name + ".step");
        if (spec["type"]) {
          const std::string type = io::YamlScalarText(spec["type"], path, d.name + ".type");
          if (type != "int" && type != "real") {
            throw InputError(path, spec["type"].Mark().line + 1,
                             fmt::format("'{}': type must be int or real, not '{}'", d.name, type));
          }
          if (d.integer && type == "real") {
            throw InputError(path, spec["type"].Mark().line + 1,
                             fmt::format("'{}' is an integer parameter: its type must be int", d.name));
          }
          d.integer = type == "int";
        }
        s.dimensions.push_back(d);
      }
    } else if (key == "fix") {
      if (!top.second.IsMap()) throw InputError(path, top.second.Mark().line + 1, "'fix' must be a map");
      for (const auto& item : top.second) {
        const std::string name = io::YamlScalarText(item.first, path, "a parameter name");
        s.lines[name] = item.first.Mark().line + 1;
        if (slam::FindParam(name) == nullptr) throw InputError(path, s.lines[name], slam::UnknownParamMessage(name));
        s.fixed[name] = ReadNumber(item.second, path, name);
      }
    } else {
      throw InputError(path, top.first.Mark().line + 1, fmt::format("unknown key '{}' (allowed: vary, fix)", key));
    }
  }
  SortRealsFirst(s.dimensions);
  s.Validate(path);
  return s;
}

std::string FullParamName(const std::string& name) {
  if (name == "r") return "loop_search_maximum_distance";
  if (name == "g") return "loop_match_minimum_chain_size";
  if (name == "p") return "loop_match_minimum_response_coarse";
  if (name == "q") return "loop_match_maximum_variance_coarse";
  return name;
}

double ParseFlagNumber(const std::string& text, const std::string& what) {
  try {
    std::size_t used = 0;
    const double v = std::stod(text, &used);
    if (used != text.size() || !std::isfinite(v)) throw std::invalid_argument(text);
    return v;
  } catch (const std::exception&) {
    throw InputError(fmt::format("{}: '{}' is not a number", what, text));
  }
}

SearchSpace SearchSpace::FromFlags(const std::vector<std::string>& vary, const std::vector<std::string>& fix) {
  SearchSpace s;
  for (const std::string& entry : vary) {
    const std::string form = fmt::format("--vary {}: write NAME=MIN:MAX or NAME=MIN:MAX:STEP", entry);
    const auto eq = entry.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError(form);
    std::vector<std::string> parts;
    for (std::string rest = entry.substr(eq + 1);;) {
      const auto colon = rest.find(':');
      parts.push_back(rest.substr(0, colon));
      if (colon == std::string::npos) break;
      rest = rest.substr(colon + 1);
    }
    if (parts.size() < 2 || parts.size() > 3) throw InputError(form);
    Dimension d;
    d.name = FullParamName(entry.substr(0, eq));
    const slam::ParamInfo* info = NumericParam(d.name, "--vary", 0);
    d.integer = info->type == slam::ParamType::kInt;
    d.lower = ParseFlagNumber(parts[0], "--vary " + d.name + " MIN");
    d.upper = ParseFlagNumber(parts[1], "--vary " + d.name + " MAX");
    if (parts.size() == 3) d.step = ParseFlagNumber(parts[2], "--vary " + d.name + " STEP");
    if (d.integer && d.step == 1.0) d.step = 0.0;  // integers move by whole numbers anyway
    s.dimensions.push_back(d);
  }
  for (const std::string& entry : fix) {
    const auto eq = entry.find('=');
    if (eq == std::string::npos || eq == 0) throw InputError(fmt::format("--fix {}: write NAME=VALUE", entry));
    const std::string name = FullParamName(entry.substr(0, eq));
    if (slam::FindParam(name) == nullptr) throw InputError("--fix: " + slam::UnknownParamMessage(name));
    if (s.fixed.count(name)) throw InputError(fmt::format("--fix {}: given twice", name));
    s.fixed[name] = ParseFlagNumber(entry.substr(eq + 1), "--fix " + name);
  }
  SortRealsFirst(s.dimensions);
  s.Validate("--vary");
  return s;
}

std::size_t SearchSpace::LineOf(const std::string& name) const {
  const auto it = lines.find(name);
  return it == lines.end() ? 0 : it->second;
}

namespace {

// The line of the searched or fixed name an engine message is about ("mapper parameter NAME = ...").
std::size_t LineOfMessage(const SearchSpace& space, const std::string& message, std::size_t fallback) {
  for (const auto& [name, line] : space.lines) {
    if (message.find("parameter " + name + " ") != std::string::npos) return line;
  }
  return fallback;
}

}  // namespace

void CheckSpaceAgainst(const SearchSpace& space, const slam::MapperParams& base, const std::string& source) {
  for (const Dimension& d : space.dimensions) {
    for (double bound : {d.lower, d.upper}) {
      std::map<std::string, double> values = space.fixed;
      values[d.name] = bound;
      slam::MapperParams probe = base;
      try {
        slam::SetNumerics(probe, values);
      } catch (const InputError& e) {
        throw InputError(source, LineOfMessage(space, e.message(), space.LineOf(d.name)), e.message());
      }
    }
  }
}

void SearchSpace::Validate(const std::string& source) const {
  if (dimensions.empty()) throw InputError(source, 0, "search space is empty: 'vary' names no parameter");
  std::set<std::string> seen;
  for (const Dimension& d : dimensions) {
    if (!seen.insert(d.name).second)
      throw InputError(source, LineOf(d.name), fmt::format("'{}' is listed twice", d.name));
    if (fixed.count(d.name))
      throw InputError(source, LineOf(d.name), fmt::format("'{}' is both varied and fixed", d.name));
    if (!std::isfinite(d.lower) || !std::isfinite(d.upper)) {
      throw InputError(source, LineOf(d.name), fmt::format("'{}': bounds must be finite", d.name));
    }
    if (!(d.lower < d.upper)) {
      throw InputError(
          source, LineOf(d.name),
          fmt::format("'{}': bounds reversed or empty (min {} must be < max {})", d.name, d.lower, d.upper));
    }
    if (!std::isfinite(d.step) || d.step < 0.0 || (d.step > 0.0 && d.step > d.upper - d.lower)) {
      throw InputError(
          source, LineOf(d.name),
          fmt::format("'{}': step {} must be > 0 and at most max - min = {}", d.name, d.step, d.upper - d.lower));
    }
    if (d.integer && d.step != std::floor(d.step)) {
      throw InputError(source, LineOf(d.name),
                       fmt::format("'{}': an int parameter needs a whole-number step, got {}", d.name, d.step));
    }
    if (d.integer && (d.lower != std::floor(d.lower) || d.upper != std::floor(d.upper))) {
      throw InputError(
          source, LineOf(d.name),
          fmt::format("'{}': an int parameter needs whole-number bounds, got [{}, {}]", d.name, d.lower, d.upper));
    }
  }
  for (const auto& [name, value] : fixed) {
    if (!std::isfinite(value)) throw InputError(source, LineOf(name), fmt::format("fixed '{}' must be finite", name));
  }
  for (std::size_t i = 1; i < dimensions.size(); ++i) {
    SLAMTUNE_CHECK_MSG(!(dimensions[i - 1].integer && !dimensions[i].integer), "integer genes must come last");
  }
}

std::size_t SearchSpace::integer_count() const {
  return static_cast<std::size_t>(
      std::count_if(dimensions.begin(), dimensions.end(), [](const Dimension& d) { return d.integer; }));
}

bool SearchSpace::VariesMapSampling() const {
  static const std::set<std::string> kSampling = {"minimum_travel_distance", "minimum_travel_heading",
                                                  "minimum_time_interval",   "max_laser_range",
                                                  "min_laser_range",         "resolution"};
  return std::any_of(dimensions.begin(), dimensions.end(),
                     [](const Dimension& d) { return kSampling.count(d.name) > 0; });
}

bool SearchSpace::VariesFrontEnd() const {
  static const std::set<std::string> kFrontEnd = {"correlation_search_space_dimension",
                                                  "correlation_search_space_resolution",
                                                  "correlation_search_space_smear_deviation",
                                                  "coarse_search_angle_offset",
                                                  "coarse_angle_resolution",
                                                  "fine_search_angle_offset",
                                                  "distance_variance_penalty",
                                                  "angle_variance_penalty",
                                                  "minimum_distance_penalty",
                                                  "minimum_angle_penalty",
                                                  "use_response_expansion",
                                                  "minimum_travel_distance",
                                                  "minimum_travel_heading",
                                                  "minimum_time_interval",
                                                  "scan_buffer_size",
                                                  "scan_buffer_maximum_scan_distance",
                                                  "throttle_scans",
                                                  "sync_minimum_time_interval"};
  return std::any_of(dimensions.begin(), dimensions.end(),
                     [](const Dimension& d) { return kFrontEnd.count(d.name) > 0; });
}

std::map<std::string, double> SearchSpace::Assign(const std::vector<double>& decision) const {
  SLAMTUNE_CHECK(decision.size() == dimensions.size());
  std::map<std::string, double> out = fixed;
  for (std::size_t i = 0; i < dimensions.size(); ++i) {
    out[dimensions[i].name] = dimensions[i].ValueOf(decision[i]);
  }
  return out;
}

std::string SearchSpace::Key(const std::map<std::string, double>& assignment) {
  std::string key;
  for (const auto& [name, value] : assignment) key += fmt::format("{}={:.17g};", name, value);
  return key;
}

std::string SearchSpace::Fingerprint() const {
  std::string f = "vary:";
  for (const Dimension& d : dimensions) {
    f += fmt::format("{}[{:.17g},{:.17g}]{}", d.name, d.lower, d.upper, d.integer ? "int" : "real");
    if (d.step > 0.0) f += fmt::format("/{:.17g}", d.step);  // spaces without steps keep their old fingerprint
    f += ";";
  }
  f += "fix:" + Key(fixed);
  return f;
}

}  // namespace slamtune::optim
