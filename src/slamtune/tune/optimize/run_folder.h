// The folder of one optimisation (--out DIR, or --resume DIR) and its run database. One process
// at a time works in it, from before its database is read to the last report file (FolderLock);
// a new run refuses a folder that holds another, and a resumed one takes what it needs from the
// folder's record (tune/optimize/optimize_options.h).
#pragma once

#include <optional>
#include <string>

#include "slamtune/common/folder_lock.h"
#include "slamtune/tune/optimize/optimize_options.h"

namespace slamtune::tune {

class RunFolder {
 public:
  // InputError for --out and --resume naming different folders, or neither.
  RunFolder(const std::string& out, const std::string& resume);

  const std::string& dir() const { return dir_; }
  const std::string& db_path() const { return db_path_; }  // DIR/run.sqlite
  bool resume() const { return resume_; }

  // Locks the folder now if it can be locked before the inputs are read: it exists and can be
  // written (else EnsureLocked creates and checks it after the inputs, and locks it then).
  void LockIfWritable();
  // Creates and checks the folder, and locks it unless it is locked already; a new run's
  // folder must not hold another.
  void EnsureLocked();
  // InputError when the folder holds a run database (a new run's folder).
  void RefuseHeldRun() const;

 private:
  std::string dir_;
  std::string db_path_;
  bool resume_ = false;
  std::optional<FolderLock> lock_;
};

// --resume: the run database must exist and be whole (PRAGMA quick_check). Its invocation record
// as the current schema (MigrateInvocation), or nullopt when it holds none.
std::optional<nlohmann::json> ReadInvocation(const RunFolder& folder);

// Before a resumed run: with `take_recorded` (--resume alone, or with options that do not change
// results) `options` become the recorded ones; the input files must still have their recorded
// content. InputError naming the folder or file otherwise.
void PrepareResume(const RunFolder& folder, bool take_recorded, OptimizeOptions& options);

}  // namespace slamtune::tune
