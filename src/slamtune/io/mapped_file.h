// A whole file as read-only bytes in memory, mapped (mmap, PROT_READ, MAP_PRIVATE) rather than
// read, so that a recording of several GB is paged in as the linear readers walk it and costs no
// copy. An empty file gives empty bytes.
#pragma once

#include <cstdint>
#include <span>
#include <string>

namespace slamtune::io {

class MappedFile {
 public:
  // Throws InputError "PATH: cannot open (reason)" for a missing, unreadable or non-regular file.
  explicit MappedFile(const std::string& path);
  ~MappedFile();
  MappedFile(const MappedFile&) = delete;
  MappedFile& operator=(const MappedFile&) = delete;

  std::span<const std::uint8_t> bytes() const { return {data_, size_}; }

 private:
  const std::uint8_t* data_ = nullptr;
  std::size_t size_ = 0;
};

// Throws InputError "PATH: cannot open (reason)" unless `path` can be opened for reading.
void CheckReadable(const std::string& path);

}  // namespace slamtune::io
