// One process at a time in an output folder: an exclusive flock(2) on DIR/run.lock, a file
// that holds the holder's pid so that a refused process can say who holds it.
//
// Why: two processes writing one run folder (a --resume while the first run still works, or a
// fresh run into the same --out) would interleave their database writes and report files.
// The lock is released by the kernel when the holder ends, however it ends (kill -9 too), so a
// stale run.lock never blocks a later run; the file itself stays in the folder.
#pragma once

#include <string>

namespace slamtune {

class FolderLock {
 public:
  // Locks the existing folder `dir`. Throws InputError "DIR: another slamtune process (pid N)
  // is working in this folder; wait for it to end or stop it" when another process (or another
  // FolderLock of this process) holds it, and "DIR/run.lock: cannot create the lock file:
  // REASON" when the file cannot be opened.
  explicit FolderLock(const std::string& dir);
  ~FolderLock();  // releases the lock
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

  const std::string& path() const { return path_; }

 private:
  std::string path_;  // DIR/run.lock
  int fd_ = -1;
};

}  // namespace slamtune
