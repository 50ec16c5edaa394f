#include "slamtune/io/ros/tf_buffer.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>

namespace slamtune::io {
namespace {

// Linear in translation, slerp in rotation, at fraction f in [0, 1] from a to b.
RigidTransform3 Interpolate(const RigidTransform3& a, const RigidTransform3& b, double f) {
  RigidTransform3 out;
  out.translation = a.translation + f * (b.translation - a.translation);
  out.rotation = a.rotation.slerp(f, b.rotation);
  return out;
}

}  // namespace

std::string StampText(std::int64_t stamp_ns) { return fmt::format("{:.6f} s", static_cast<double>(stamp_ns) / 1e9); }

RigidTransform3 RigidTransform3::operator*(const RigidTransform3& other) const {
  RigidTransform3 out;
  out.translation = translation + rotation * other.translation;
  out.rotation = rotation * other.rotation;
  return out;
}

RigidTransform3 RigidTransform3::Inverse() const {
  RigidTransform3 out;
  out.rotation = rotation.conjugate();
  out.translation = -(out.rotation * translation);
  return out;
}

std::string NormalizeFrameId(const std::string& frame) {
  return !frame.empty() && frame.front() == '/' ? frame.substr(1) : frame;
}

double YawOf(const Eigen::Quaterniond& q) {
  return std::atan2(2.0 * (q.w() * q.z() + q.x() * q.y()), 1.0 - 2.0 * (q.y() * q.y() + q.z() * q.z()));
}

Pose2 ToPose2(const RigidTransform3& t) { return {t.translation.x(), t.translation.y(), YawOf(t.rotation)}; }

bool TfBuffer::Add(const std::string& parent, const std::string& child, std::int64_t stamp_ns, const RigidTransform3& t,
                   bool is_static, std::int64_t received_ns) {
  // tf2 refuses rotations whose squared norm is more than 0.01 from 1, and so does this.
  const double norm2 = t.rotation.squaredNorm();
  if (!std::isfinite(norm2) || std::fabs(norm2 - 1.0) > 0.01 || !t.translation.allFinite()) {
    ++bad_rotations_;
    return false;
  }
  if (parent.empty() || child.empty() || parent == child) {
    ++refused_frames_;  // tf2: "TF_NO_FRAME_ID", "TF_NO_CHILD_FRAME_ID", "TF_SELF_TRANSFORM"
    return false;
  }
  auto [it, inserted] = edges_.try_emplace(child);
  Edge& edge = it->second;
  if (inserted) {
    edge.parent = parent;
    edge.is_static = is_static;
  } else if (edge.parent != parent) {
    ++parent_conflicts_;
    return false;
  }
  RigidTransform3 normalised = t;
  if (norm2 != 1.0) normalised.rotation.normalize();  // a unit quaternion stays bit for bit
  ++transforms_;
  if (is_static || edge.is_static) {
    // A static edge holds one transform at all times; a later message replaces it (latched
    // /tf_static republished). A frame once static stays static.
    edge.is_static = true;
    edge.samples.assign(1, Sample{stamp_ns, normalised, received_ns});
    return true;
  }
  if (!edge.samples.empty() && stamp_ns < edge.samples.back().stamp_ns) edge.sorted = false;
  edge.samples.push_back(Sample{stamp_ns, normalised, received_ns});
  return true;
}

void TfBuffer::SortEdges() const {
  for (auto& [child, edge] : edges_) {
    if (edge.sorted) continue;
    std::stable_sort(edge.samples.begin(), edge.samples.end(),
                     [](const Sample& a, const Sample& b) { return a.stamp_ns < b.stamp_ns; });
    edge.sorted = true;
  }
}

TfLookup TfBuffer::EdgeAt(const std::string& child, const Edge& edge, std::int64_t stamp_ns,
                          std::int64_t max_gap_ns) const {
  if (edge.is_static) return {edge.samples.front().transform, ""};
  const auto& s = edge.samples;
  auto after =
      std::lower_bound(s.begin(), s.end(), stamp_ns, [](const Sample& a, std::int64_t t) { return a.stamp_ns < t; });
  if (after != s.end() && after->stamp_ns == stamp_ns) return {after->transform, ""};
  if (after == s.begin() || after == s.end()) {
    return {std::nullopt,
            fmt::format("{} -> {} at {}: outside its samples ({} .. {})", edge.parent, child, StampText(stamp_ns),
                        StampText(s.front().stamp_ns), StampText(s.back().stamp_ns))};
  }
  const Sample& b = *after;
  const Sample& a = *(after - 1);
  if (b.stamp_ns - a.stamp_ns > max_gap_ns) {
    return {std::nullopt, fmt::format("{} -> {} at {}: no sample for {:.3f} s around it (gap {} .. {})", edge.parent,
                                      child, StampText(stamp_ns), static_cast<double>(b.stamp_ns - a.stamp_ns) / 1e9,
                                      StampText(a.stamp_ns), StampText(b.stamp_ns))};
  }
  const double f = static_cast<double>(stamp_ns - a.stamp_ns) / static_cast<double>(b.stamp_ns - a.stamp_ns);
  return {Interpolate(a.transform, b.transform, f), ""};
}

bool TfBuffer::HasFrame(const std::string& frame) const {
  if (edges_.count(frame) != 0) return true;
  return std::any_of(edges_.begin(), edges_.end(), [&](const auto& e) { return e.second.parent == frame; });
}

std::vector<std::string> TfBuffer::PathToRoot(const std::string& frame) const {
  std::vector<std::string> path{frame};
  for (auto it = edges_.find(frame); it != edges_.end(); it = edges_.find(path.back())) {
    if (std::find(path.begin(), path.end(), it->second.parent) != path.end()) break;  // a cycle
    path.push_back(it->second.parent);
  }
  return path;
}

std::vector<std::string> TfBuffer::LoopAbove(const std::string& frame) const {
  std::vector<std::string> up{frame};  // each frame's parent follows it
  for (auto it = edges_.find(frame); it != edges_.end(); it = edges_.find(up.back())) {
    const auto seen = std::find(up.begin(), up.end(), it->second.parent);
    if (seen == up.end()) {
      up.push_back(it->second.parent);
      continue;
    }
    // up[j] ... up[k] read upwards, and up[k]'s parent is up[j]: as the transforms go, up[j]
    // is the parent of up[k], up[k] of up[k - 1], ..., up[j + 1] of up[j].
    const auto j = static_cast<std::size_t>(seen - up.begin());
    std::vector<std::string> loop{up[j]};
    for (std::size_t i = up.size(); i-- > j + 1;) loop.push_back(up[i]);
    loop.push_back(up[j]);
    return loop;
  }
  return {};
}

std::vector<std::vector<std::string>> TfBuffer::Loops() const {
  std::vector<std::vector<std::string>> loops;
  for (const auto& [child, edge] : edges_) {
    std::vector<std::string> loop = LoopAbove(child);
    if (loop.empty()) continue;
    loop.pop_back();
    std::rotate(loop.begin(), std::min_element(loop.begin(), loop.end()), loop.end());
    loop.push_back(loop.front());
    if (std::find(loops.begin(), loops.end(), loop) == loops.end()) loops.push_back(std::move(loop));
  }
  std::sort(loops.begin(), loops.end());
  return loops;
}

namespace {
constexpr std::int64_t kNoGapLimitNs = std::numeric_limits<std::int64_t>::max();
}  // namespace

TfLookup TfBuffer::Lookup(const std::string& target, const std::string& source, std::int64_t stamp_ns,
                          double max_gap_s) const {
  SortEdges();
  // In nanoseconds, held to what an int64 holds (a negative gap is none, a huge one no limit).
  const double gap_ns = max_gap_s * 1e9;
  const std::int64_t max_gap_ns = !(gap_ns > 0.0)                                ? 0
                                  : gap_ns >= static_cast<double>(kNoGapLimitNs) ? kNoGapLimitNs
                                                                                 : static_cast<std::int64_t>(gap_ns);
  for (const std::string& frame : {target, source}) {
    if (!HasFrame(frame)) return {std::nullopt, fmt::format("frame '{}' is in no transform", frame)};
  }
  const std::vector<std::string> up_source = PathToRoot(source), up_target = PathToRoot(target);
  auto common = std::find_first_of(up_source.begin(), up_source.end(), up_target.begin(), up_target.end());
  if (common == up_source.end()) {
    return {std::nullopt, fmt::format("'{}' and '{}' are not connected (roots '{}' and '{}')", target, source,
                                      up_target.back(), up_source.back())};
  }
  // source in ancestor, and target in ancestor, each composed down from the ancestor.
  const auto chain = [&](const std::vector<std::string>& up, const std::string& ancestor) -> TfLookup {
    RigidTransform3 t;
    for (const std::string& frame : up) {
      if (frame == ancestor) break;
      const TfLookup edge = EdgeAt(frame, edges_.at(frame), stamp_ns, max_gap_ns);
      if (!edge.transform) return edge;
      t = *edge.transform * t;
    }
    return {t, ""};
  };
  const TfLookup source_in_ancestor = chain(up_source, *common);
  if (!source_in_ancestor.transform) return source_in_ancestor;
  const TfLookup target_in_ancestor = chain(up_target, *common);
  if (!target_in_ancestor.transform) return target_in_ancestor;
  if (*common == target) return source_in_ancestor;  // the usual case: target is an ancestor, exact
  return {target_in_ancestor.transform->Inverse() * *source_in_ancestor.transform, ""};
}

std::vector<std::string> TfBuffer::Describe() const {
  std::vector<std::string> out;
  for (const auto& [child, edge] : edges_) {
    out.push_back(edge.is_static ? fmt::format("{} -> {} (static)", edge.parent, child)
                                 : fmt::format("{} -> {} ({} samples)", edge.parent, child, edge.samples.size()));
  }
  return out;
}

std::vector<std::int64_t> TfBuffer::SampleStamps(const std::string& child) const {
  SortEdges();
  std::vector<std::int64_t> out;
  auto it = edges_.find(child);
  if (it == edges_.end() || it->second.is_static) return out;
  for (const Sample& s : it->second.samples) out.push_back(s.stamp_ns);
  return out;
}

std::vector<std::int64_t> TfBuffer::SampleReceiveTimes(const std::string& child) const {
  SortEdges();
  std::vector<std::int64_t> out;
  auto it = edges_.find(child);
  if (it == edges_.end() || it->second.is_static) return out;
  for (const Sample& s : it->second.samples) out.push_back(s.received_ns);
  return out;
}

bool TfBuffer::IsStatic(const std::string& child) const {
  auto it = edges_.find(child);
  return it != edges_.end() && it->second.is_static;
}

std::string TfBuffer::ParentOf(const std::string& child) const {
  auto it = edges_.find(child);
  return it == edges_.end() ? "" : it->second.parent;
}

}  // namespace slamtune::io
