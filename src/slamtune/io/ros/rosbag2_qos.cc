#include "slamtune/io/ros/rosbag2_qos.h"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cctype>
#include <exception>
#include <string>

namespace slamtune::io {
namespace {

constexpr int kDurabilityTransientLocal = 1;  // rmw_qos_durability_policy_e

bool IsTransientLocal(const YAML::Node& profile) {
  if (!profile.IsMap()) return false;
  const YAML::Node durability = profile["durability"];
  if (!durability || !durability.IsScalar()) return false;
  std::string value = durability.Scalar();
  std::transform(value.begin(), value.end(), value.begin(), [](unsigned char c) { return std::tolower(c); });
  return value == "transient_local" || value == std::to_string(kDurabilityTransientLocal);
}

}  // namespace

bool OfferedQosIsTransientLocal(std::string_view offered_qos_profiles) {
  if (offered_qos_profiles.empty()) return false;
  try {
    YAML::Node profiles = YAML::Load(std::string(offered_qos_profiles));
    if (profiles.IsScalar()) profiles = YAML::Load(profiles.Scalar());  // a YAML string holding the list
    if (!profiles.IsSequence()) return false;
    for (const YAML::Node& profile : profiles) {
      if (IsTransientLocal(profile)) return true;
    }
  } catch (const std::exception&) {
    return false;
  }
  return false;
}

}  // namespace slamtune::io
