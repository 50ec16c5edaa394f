#include "slamtune/io/byte_cursor.h"

#include <string>

#include "slamtune/common/error.h"

namespace slamtune::io {
namespace {

// Little-endian, whatever the host order.
std::uint64_t LoadLittleEndian(const std::uint8_t* p, int size) {
  std::uint64_t value = 0;
  for (int i = size - 1; i >= 0; --i) value = (value << 8) | p[i];
  return value;
}

}  // namespace

void ThrowAtByte(std::string_view file, std::string_view frame, std::uint64_t offset, std::string_view what,
                 std::string_view problem) {
  std::string message(frame);
  message += "byte " + std::to_string(offset) + " (";
  message += what;
  message += "): ";
  message += problem;
  throw InputError(std::string(file), 0, message);
}

ByteCursor::ByteCursor(std::span<const std::uint8_t> bytes, std::string_view file, std::uint64_t first_offset,
                       std::string_view frame)
    : bytes_(bytes), file_(file), first_offset_(first_offset), frame_(frame) {}

void ByteCursor::Fail(std::uint64_t offset, std::string_view what, std::string_view problem) const {
  ThrowAtByte(file_, frame_, offset, what, problem);
}

const std::uint8_t* ByteCursor::Take(std::uint64_t n, std::string_view what) {
  if (n > remaining()) {
    Fail(offset(), what, "needs " + std::to_string(n) + " bytes, " + std::to_string(remaining()) + " left");
  }
  const std::uint8_t* start = bytes_.data() + position_;
  position_ += static_cast<std::size_t>(n);
  return start;
}

std::uint8_t ByteCursor::U8(std::string_view what) { return *Take(1, what); }
std::uint16_t ByteCursor::U16(std::string_view what) {
  return static_cast<std::uint16_t>(LoadLittleEndian(Take(2, what), 2));
}
std::uint32_t ByteCursor::U32(std::string_view what) {
  return static_cast<std::uint32_t>(LoadLittleEndian(Take(4, what), 4));
}
std::uint64_t ByteCursor::U64(std::string_view what) { return LoadLittleEndian(Take(8, what), 8); }

std::span<const std::uint8_t> ByteCursor::Bytes(std::uint64_t n, std::string_view what) {
  const std::uint8_t* start = Take(n, what);
  return {start, static_cast<std::size_t>(n)};
}

std::span<const std::uint8_t> ByteCursor::BytesU32(std::string_view what) {
  const std::uint64_t start = offset();
  return LengthPrefixed(start, U32(what), what);
}

std::span<const std::uint8_t> ByteCursor::BytesU64(std::string_view what) {
  const std::uint64_t start = offset();
  return LengthPrefixed(start, U64(what), what);
}

std::span<const std::uint8_t> ByteCursor::LengthPrefixed(std::uint64_t start, std::uint64_t n, std::string_view what) {
  if (n > remaining()) {
    Fail(start, what,
         "length " + std::to_string(n) + " runs past the end (" + std::to_string(remaining()) + " bytes left)");
  }
  return Bytes(n, what);
}

std::string_view ByteCursor::StringU32(std::string_view what) {
  const auto bytes = BytesU32(what);
  return {reinterpret_cast<const char*>(bytes.data()), bytes.size()};
}

std::span<const std::uint8_t> ByteCursor::Rest() { return Bytes(remaining(), "rest"); }

}  // namespace slamtune::io
