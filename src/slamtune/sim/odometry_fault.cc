#include "slamtune/sim/odometry_fault.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "slamtune/common/error.h"
#include "slamtune/common/karto_math.h"

namespace slamtune::sim {

std::string_view OdometryFaultKindName(OdometryFaultKind kind) {
  switch (kind) {
    case OdometryFaultKind::kSpin: return "spin";
    case OdometryFaultKind::kJump: return "jump";
    case OdometryFaultKind::kReverse: return "reverse";
  }
  return "?";
}

std::optional<OdometryFaultKind> ParseOdometryFaultKind(std::string_view name) {
  for (OdometryFaultKind kind : {OdometryFaultKind::kSpin, OdometryFaultKind::kJump, OdometryFaultKind::kReverse}) {
    if (name == OdometryFaultKindName(kind)) return kind;
  }
  return std::nullopt;
}

void OdometryFault::Validate(const std::string& field) const {
  const std::string_view name = OdometryFaultKindName(kind);
  if (!(std::isfinite(start_m) && start_m >= 0.0)) {
    throw InputError(fmt::format("{} ({}) start_m = {}: must be finite and >= 0", field, name, start_m));
  }
  if (!(std::isfinite(length_m) && length_m > 0.0)) {
    throw InputError(fmt::format("{} ({}) length_m = {}: must be finite and > 0", field, name, length_m));
  }
  const auto bound = [&](double limit, const char* unit) {
    if (!(std::fabs(magnitude) <= limit)) {
      throw InputError(
          fmt::format("{} ({}) magnitude = {}: must be in [-{}, {}] {}", field, name, magnitude, limit, limit, unit));
    }
  };
  switch (kind) {
    case OdometryFaultKind::kSpin: bound(2.0 * kPi, "rad"); break;
    case OdometryFaultKind::kJump: bound(10.0, "m"); break;
    case OdometryFaultKind::kReverse:
      if (magnitude != 0.0) {
        throw InputError(fmt::format("{} (reverse) magnitude = {}: must be 0 (reverse takes none)", field, magnitude));
      }
      break;
  }
}

std::string OdometryFault::Describe() const {
  const std::string where = fmt::format("{} at {} m over {} m", OdometryFaultKindName(kind), start_m, length_m);
  switch (kind) {
    case OdometryFaultKind::kSpin:
      return fmt::format("{}: {:.4g} deg reported, not turned", where, RadToDeg(magnitude));
    case OdometryFaultKind::kJump: return fmt::format("{}: {} m reported, not travelled", where, magnitude);
    case OdometryFaultKind::kReverse: return where + ": travel reported backwards";
  }
  return where;
}

FaultEffect FaultEffectOnStep(const std::vector<OdometryFault>& faults, double from_m, double distance_m) {
  FaultEffect effect;
  if (!(distance_m > 0.0)) return effect;
  const double to_m = from_m + distance_m;
  for (const OdometryFault& fault : faults) {
    const double overlap = std::min(to_m, fault.start_m + fault.length_m) - std::max(from_m, fault.start_m);
    if (!(overlap > 0.0)) continue;
    effect.active = true;
    switch (fault.kind) {
      case OdometryFaultKind::kSpin: effect.extra_rotation += fault.magnitude * overlap / fault.length_m; break;
      case OdometryFaultKind::kJump: effect.extra_distance += fault.magnitude * overlap / fault.length_m; break;
      case OdometryFaultKind::kReverse: effect.extra_distance -= 2.0 * overlap; break;
    }
  }
  return effect;
}

OdometryFault ParseOdometryFault(const std::string& text) {
  const auto fail = [&](const std::string& why) -> InputError {
    return InputError(
        fmt::format("--fault '{}': {} (expected KIND,START_M,LENGTH_M[,MAGNITUDE] with KIND spin "
                    "(degrees), jump (m) or reverse (no magnitude))",
                    text, why));
  };
  std::vector<std::string> parts;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = text.find(',', begin);
    parts.push_back(text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin));
    if (comma == std::string::npos) break;
    begin = comma + 1;
  }
  const std::optional<OdometryFaultKind> kind = ParseOdometryFaultKind(parts[0]);
  if (!kind) throw fail("unknown kind '" + parts[0] + "'");
  const std::size_t expected = *kind == OdometryFaultKind::kReverse ? 3 : 4;
  if (parts.size() != expected) throw fail(fmt::format("{} takes {} fields, got {}", parts[0], expected, parts.size()));
  std::vector<double> values;
  for (std::size_t i = 1; i < parts.size(); ++i) {
    char* end = nullptr;
    const double value = std::strtod(parts[i].c_str(), &end);
    if (parts[i].empty() || end != parts[i].c_str() + parts[i].size()) throw fail("'" + parts[i] + "' is not a number");
    values.push_back(value);
  }
  OdometryFault fault;
  fault.kind = *kind;
  fault.start_m = values[0];
  fault.length_m = values[1];
  if (values.size() > 2) fault.magnitude = *kind == OdometryFaultKind::kSpin ? DegToRad(values[2]) : values[2];
  fault.Validate("--fault '" + text + "'");
  return fault;
}

}  // namespace slamtune::sim
