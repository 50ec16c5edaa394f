#include "slamtune/slam/run_trace.h"

#include <cerrno>
#include <cstring>

#include "slamtune/common/error.h"

namespace slamtune::slam {
namespace {

// Spaces in free text (a solver's termination reason) become underscores: one token per field.
std::string Token(const std::string& text) {
  std::string out = text.empty() ? "-" : text;
  for (char& c : out) {
    if (c == ' ' || c == '\t' || c == '\n') c = '_';
  }
  return out;
}

}  // namespace

RunTrace::RunTrace(const std::string& path) : path_(path), file_(std::fopen(path.c_str(), "w")) {
  if (file_ == nullptr) throw InputError(path, 0, std::string("cannot write the trace: ") + std::strerror(errno));
  std::fprintf(file_, "# slamtune trace 1: match and solve lines, docs/trace.md\n");
}

RunTrace::~RunTrace() {
  if (file_ != nullptr) std::fclose(file_);
}

void RunTrace::WriteMatch(const TracedMatch& m) {
  if (file_ == nullptr) return;
  const Eigen::Matrix3d& c = m.covariance;
  std::fprintf(file_,
               "match %s %d %d %d %d %d %.17g %.17g %.17g %.17g %.17g %.17g %.17g "
               "%.17g %.17g %.17g %.17g %.17g %.17g %s\n",
               m.kind, m.log_index, m.scan, m.base_first, m.base_last, m.base_size, m.pose_in.x, m.pose_in.y,
               m.pose_in.theta, m.response, m.mean.x, m.mean.y, m.mean.theta, c(0, 0), c(0, 1), c(0, 2), c(1, 1),
               c(1, 2), c(2, 2), m.decision);
}

void RunTrace::WriteSolve(int index, int nodes, int edges, const SolveSummary& s) {
  if (file_ == nullptr) return;
  std::fprintf(file_, "solve %d %s %d %d %.17g %.17g %d %d %d %s\n", index, s.backend.c_str(), nodes, edges,
               s.initial_cost, s.final_cost, s.iterations, s.accepted_steps, s.cholesky_failures,
               Token(s.termination).c_str());
  for (std::size_t k = 0; k < s.steps.size(); ++k) {
    std::fprintf(file_, "step %d %zu %.17g %s\n", index, k, s.steps[k].cost,
                 s.steps[k].accepted ? "accepted" : "rejected");
  }
}

void RunTrace::Close() {
  if (file_ == nullptr) return;
  const bool ok = std::fflush(file_) == 0 && std::ferror(file_) == 0;
  const bool closed = std::fclose(file_) == 0;
  file_ = nullptr;
  if (!ok || !closed) throw InputError(path_, 0, "the trace could not be written completely");
}

}  // namespace slamtune::slam
