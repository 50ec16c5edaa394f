// Whether a rosbag2 topic was recorded as latched, from its offered_qos_profiles: the YAML list
// of QoS profiles of the topic's publishers, found in a db3 `topics` column, an MCAP Channel's
// metadata and metadata.yaml (there as a YAML string holding the list, so parsed twice).
// Durability is written as an rmw enum integer by Humble (1 = transient_local) and as a name by
// Jazzy and later ("transient_local") (docs/recordings.md §1.7).
#pragma once

#include <string_view>

namespace slamtune::io {

// True when any profile has durability transient_local. Malformed or empty text: false (the
// QoS is informational; it never makes a recording unreadable).
bool OfferedQosIsTransientLocal(std::string_view offered_qos_profiles);

}  // namespace slamtune::io
