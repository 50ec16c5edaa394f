#include "slamtune/io/mapped_file.h"

#include <fcntl.h>
#include <sys/mman.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include "slamtune/common/error.h"

namespace slamtune::io {
namespace {

[[noreturn]] void ThrowCannotOpen(const std::string& path, int error) {
  throw InputError(path, 0, std::string("cannot open (") + std::strerror(error) + ")");
}

// Closes a file descriptor when it goes out of scope.
struct FileDescriptor {
  int fd = -1;
  ~FileDescriptor() {
    if (fd >= 0) ::close(fd);
  }
};

}  // namespace

void CheckReadable(const std::string& path) {
  FileDescriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) ThrowCannotOpen(path, errno);
}

MappedFile::MappedFile(const std::string& path) {
  FileDescriptor file{::open(path.c_str(), O_RDONLY | O_CLOEXEC)};
  if (file.fd < 0) ThrowCannotOpen(path, errno);
  struct stat info {};
  if (::fstat(file.fd, &info) != 0) ThrowCannotOpen(path, errno);
  if (S_ISDIR(info.st_mode)) ThrowCannotOpen(path, EISDIR);
  if (!S_ISREG(info.st_mode)) throw InputError(path, 0, "cannot open (not a regular file)");
  size_ = static_cast<std::size_t>(info.st_size);
  if (size_ == 0) return;
  void* mapped = ::mmap(nullptr, size_, PROT_READ, MAP_PRIVATE, file.fd, 0);
  if (mapped == MAP_FAILED) ThrowCannotOpen(path, errno);
  ::madvise(mapped, size_, MADV_SEQUENTIAL);  // the readers walk the file front to back
  data_ = static_cast<const std::uint8_t*>(mapped);
}

MappedFile::~MappedFile() {
  if (data_ != nullptr) ::munmap(const_cast<std::uint8_t*>(data_), size_);
}

}  // namespace slamtune::io
