#include "slamtune/common/folder_lock.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>

#include "slamtune/common/error.h"

namespace slamtune {
namespace {

// The pid written by the holder, or "?" when it cannot be read yet.
std::string HolderPid(int fd) {
  char buffer[32] = {};
  const ssize_t n = pread(fd, buffer, sizeof(buffer) - 1, 0);
  std::string text = n > 0 ? std::string(buffer, static_cast<std::size_t>(n)) : "";
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text.empty() ? "?" : text;
}

void WritePid(int fd) {
  const std::string pid = std::to_string(getpid()) + "\n";
  if (ftruncate(fd, 0) == 0) {
    [[maybe_unused]] const ssize_t n = pwrite(fd, pid.data(), pid.size(), 0);
  }
}

}  // namespace

FolderLock::FolderLock(const std::string& dir) : path_((std::filesystem::path(dir) / "run.lock").string()) {
  fd_ = open(path_.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0) throw InputError(path_, 0, std::string("cannot create the lock file: ") + std::strerror(errno));
  if (flock(fd_, LOCK_EX | LOCK_NB) != 0) {
    const int error = errno;
    const std::string pid = error == EWOULDBLOCK ? HolderPid(fd_) : "";
    close(fd_);
    fd_ = -1;
    if (error != EWOULDBLOCK) throw InputError(path_, 0, std::string("cannot lock: ") + std::strerror(error));
    throw InputError(dir, 0,
                     "another slamtune process (pid " + pid +
                         ") is working in this folder; wait for it to end or "
                         "stop it");
  }
  WritePid(fd_);
}

FolderLock::~FolderLock() {
  if (fd_ >= 0) close(fd_);  // closing the last descriptor releases the flock
}

}  // namespace slamtune
