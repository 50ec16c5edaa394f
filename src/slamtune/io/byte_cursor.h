// A bounds-checked little-endian reader over bytes in memory, for the binary container formats
// (MCAP: mcap.dev/spec "Serialization"; ROS 1 bag v2.0: wiki.ros.org/Bags/Format/2.0), whose
// integers are all little-endian and whose strings and byte fields carry a u32 or u64 length.
//
// Every read that would run past the end throws InputError "FILE: FRAMEbyte N (WHAT): needs K
// bytes, M left", N the absolute offset of the read in the file (first_offset + position), so a
// truncated or corrupt file is reported where it is. FRAME locates bytes that are not the file's
// own, e.g. "byte 18213 (chunk), uncompressed " for the records inside a decompressed chunk.
// Nothing is copied: strings and byte fields are views into the underlying bytes.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

namespace slamtune::io {

// Throws InputError(file, 0, "<frame>byte <offset> (<what>): <problem>").
[[noreturn]] void ThrowAtByte(std::string_view file, std::string_view frame, std::uint64_t offset,
                              std::string_view what, std::string_view problem);

class ByteCursor {
 public:
  // `file` and `frame` are only referenced: they must outlive the cursor. `first_offset` is the
  // offset of bytes[0] in what the messages name (the file, or a chunk's uncompressed records).
  ByteCursor(std::span<const std::uint8_t> bytes, std::string_view file, std::uint64_t first_offset = 0,
             std::string_view frame = {});

  std::uint8_t U8(std::string_view what);
  std::uint16_t U16(std::string_view what);
  std::uint32_t U32(std::string_view what);
  std::uint64_t U64(std::string_view what);
  // The next `n` bytes.
  std::span<const std::uint8_t> Bytes(std::uint64_t n, std::string_view what);
  // A u32 (resp. u64) byte length, then that many bytes.
  std::span<const std::uint8_t> BytesU32(std::string_view what);
  std::span<const std::uint8_t> BytesU64(std::string_view what);
  // A u32 byte length, then the characters (no NUL), as MCAP String.
  std::string_view StringU32(std::string_view what);
  // Everything not read yet.
  std::span<const std::uint8_t> Rest();
  void Skip(std::uint64_t n, std::string_view what) { Bytes(n, what); }

  // Throws as a failed read would, at absolute offset `offset`.
  [[noreturn]] void Fail(std::uint64_t offset, std::string_view what, std::string_view problem) const;

  std::size_t position() const { return position_; }  // bytes read so far
  std::size_t remaining() const { return bytes_.size() - position_; }
  bool empty() const { return position_ == bytes_.size(); }
  std::uint64_t offset() const { return first_offset_ + position_; }  // absolute offset of the next read
  std::string_view file() const { return file_; }
  std::string_view frame() const { return frame_; }

 private:
  // Checks that `n` bytes remain, then returns where they start and moves past them.
  const std::uint8_t* Take(std::uint64_t n, std::string_view what);
  // The `n` bytes after a length prefix that started at absolute offset `start`.
  std::span<const std::uint8_t> LengthPrefixed(std::uint64_t start, std::uint64_t n, std::string_view what);

  std::span<const std::uint8_t> bytes_;
  std::string_view file_;
  std::uint64_t first_offset_ = 0;
  std::string_view frame_;
  std::size_t position_ = 0;
};

}  // namespace slamtune::io
