#include "slamtune/tune/optimize/run_folder.h"

#include <unistd.h>

#include <filesystem>

#include "slamtune/common/error.h"
#include "slamtune/optim/evaluation_store.h"
#include "slamtune/tune/tuning_inputs.h"

namespace slamtune::tune {

RunFolder::RunFolder(const std::string& out, const std::string& resume) : resume_(!resume.empty()) {
  if (resume_ && !out.empty() && out != resume) {
    throw InputError("give either --out DIR or --resume DIR, not both with different folders");
  }
  dir_ = resume_ ? resume : out;
  if (dir_.empty()) throw InputError("--out DIR is required (or --resume DIR to continue a run)");
  db_path_ = (std::filesystem::path(dir_) / "run.sqlite").string();
}

void RunFolder::LockIfWritable() {
  if (std::filesystem::is_directory(dir_) && access(dir_.c_str(), W_OK) == 0) lock_.emplace(dir_);
}

void RunFolder::EnsureLocked() {
  EnsureWritableOutputFolder(dir_);
  if (!lock_) {
    lock_.emplace(dir_);
    if (!resume_) RefuseHeldRun();
  }
}

void RunFolder::RefuseHeldRun() const {
  if (std::filesystem::exists(db_path_)) {
    throw InputError(dir_, 0, "already holds an optimisation; use --resume DIR or a new --out");
  }
}

std::optional<nlohmann::json> ReadInvocation(const RunFolder& folder) {
  if (!std::filesystem::exists(folder.db_path())) {
    throw InputError(folder.dir(), 0, "--resume: not a slamtune optimisation folder (no run.sqlite)");
  }
  optim::CheckRunDatabase(folder.db_path());
  std::optional<nlohmann::json> stored = optim::EvaluationStore(folder.db_path()).Meta("invocation");
  if (!stored || stored->is_null()) return std::nullopt;
  return MigrateInvocation(std::move(*stored), folder.db_path());
}

void PrepareResume(const RunFolder& folder, bool take_recorded, OptimizeOptions& options) {
  const std::optional<nlohmann::json> invocation = ReadInvocation(folder);
  if (take_recorded) {
    if (!invocation) throw InputError(folder.db_path(), 0, "--resume: the run database holds no command line");
    options = OptimizeOptions::FromJson(*invocation);
  }
  if (invocation) RequireRecordedContent(*invocation, options.inputs);
}

}  // namespace slamtune::tune
