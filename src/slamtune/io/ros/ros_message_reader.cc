#include "slamtune/io/ros/ros_message_reader.h"

#include <bit>

#include "slamtune/common/error.h"

namespace slamtune::io {
namespace {

constexpr std::size_t kEncapsulationBytes = 4;
constexpr std::int64_t kNanosecondsPerSecond = 1'000'000'000;

// Representation identifiers (bytes 0-1 of the encapsulation header, big-endian): RTPS 2.5
// Table 10.3 and DDS-XTypes 1.3 7.6.3.1.2. ROS 2 writes XCDR1 plain CDR only (rmw_fastrtps pins
// it), so only the first two are read.
const char* EncapsulationKindName(std::uint16_t kind) {
  switch (kind) {
    case 0x0000: return "CDR_BE, XCDR1 plain big-endian";
    case 0x0001: return "CDR_LE, XCDR1 plain little-endian";
    case 0x0002: return "PL_CDR_BE, XCDR1 parameter list big-endian";
    case 0x0003: return "PL_CDR_LE, XCDR1 parameter list little-endian";
    case 0x0004: return "XML";
    case 0x0006: return "CDR2_BE, XCDR2 plain big-endian";
    case 0x0007: return "CDR2_LE, XCDR2 plain little-endian";
    case 0x0008: return "D_CDR2_BE, XCDR2 delimited big-endian";
    case 0x0009: return "D_CDR2_LE, XCDR2 delimited little-endian";
    case 0x000a: return "PL_CDR2_BE, XCDR2 parameter list big-endian";
    case 0x000b: return "PL_CDR2_LE, XCDR2 parameter list little-endian";
    default: return "unknown";
  }
}

std::string Hex2(std::uint8_t byte) {
  constexpr char kDigits[] = "0123456789abcdef";
  return {kDigits[byte >> 4], kDigits[byte & 0xf]};
}

}  // namespace

const char* RosWireFormatName(RosWireFormat format) {
  switch (format) {
    case RosWireFormat::kCdrLittleEndian: return "CDR little-endian";
    case RosWireFormat::kCdrBigEndian: return "CDR big-endian";
    case RosWireFormat::kRos1: return "ROS 1";
  }
  return "?";
}

RosMessageReader::RosMessageReader(std::span<const std::uint8_t> data, MessageSerialization serialization,
                                   std::string_view type)
    : data_(data), type_(type) {
  if (serialization == MessageSerialization::kCdr) ReadEncapsulation();
}

void RosMessageReader::ReadEncapsulation() {
  if (data_.size() < kEncapsulationBytes) {
    Fail("encapsulation header",
         "a CDR payload of " + std::to_string(data_.size()) + " bytes cannot hold the 4-byte encapsulation header", 0);
  }
  const std::uint16_t kind = static_cast<std::uint16_t>(data_[0] << 8 | data_[1]);
  if (kind == 0x0001) {
    format_ = RosWireFormat::kCdrLittleEndian;
  } else if (kind == 0x0000) {
    format_ = RosWireFormat::kCdrBigEndian;
  } else {
    Fail("encapsulation header",
         "representation " + Hex2(data_[0]) + " " + Hex2(data_[1]) + " (" + EncapsulationKindName(kind) +
             ") is not supported, only XCDR1 plain CDR (00 01 little-endian, 00 00 big-endian)",
         0);
  }
  offset_ = kEncapsulationBytes;  // bytes 2-3 are options, which a reader does not interpret
}

void RosMessageReader::Fail(std::string_view field, const std::string& what, std::size_t offset) const {
  std::string message(type_);
  message += ": ";
  if (!context_.empty()) message += context_ + ".";
  message += field;
  message += ": " + what + " at byte " + std::to_string(offset) + ", the message has " + std::to_string(data_.size());
  throw InputError(message);
}

std::size_t RosMessageReader::Aligned(std::size_t element_size) const {
  if (format_ == RosWireFormat::kRos1 || element_size <= 1) return offset_;
  const std::size_t misalignment = (offset_ - kEncapsulationBytes) % element_size;
  return misalignment == 0 ? offset_ : offset_ + (element_size - misalignment);
}

std::size_t RosMessageReader::ClaimPrimitive(std::string_view field, std::size_t element_size, const char* name) {
  const std::size_t at = Aligned(element_size);
  if (!Fits(at, element_size)) {
    Fail(field, std::string("a ") + name + " needs " + std::to_string(element_size) + " bytes", at);
  }
  offset_ = at + element_size;
  return at;
}

std::size_t RosMessageReader::ClaimElements(std::string_view field, std::size_t element_size, std::uint64_t count,
                                            const char* name) {
  if (count == 0) return offset_;
  const std::size_t at = Aligned(element_size);
  const std::uint64_t bytes = count * element_size;  // count < 2^32, element_size <= 8: no overflow
  if (!Fits(at, bytes)) {
    Fail(field, std::to_string(count) + " " + name + " values need " + std::to_string(bytes) + " bytes", at);
  }
  offset_ = at + static_cast<std::size_t>(bytes);
  return at;
}

std::uint32_t RosMessageReader::LoadUint32(std::size_t at) const {
  const std::uint8_t* p = data_.data() + at;
  if (format_ == RosWireFormat::kCdrBigEndian) {
    return std::uint32_t{p[0]} << 24 | std::uint32_t{p[1]} << 16 | std::uint32_t{p[2]} << 8 | std::uint32_t{p[3]};
  }
  return std::uint32_t{p[3]} << 24 | std::uint32_t{p[2]} << 16 | std::uint32_t{p[1]} << 8 | std::uint32_t{p[0]};
}

std::uint64_t RosMessageReader::LoadUint64(std::size_t at) const {
  const std::uint64_t first = LoadUint32(at);
  const std::uint64_t second = LoadUint32(at + 4);
  return format_ == RosWireFormat::kCdrBigEndian ? first << 32 | second : second << 32 | first;
}

template <typename Float>
Float RosMessageReader::LoadFloat(std::size_t at) const {
  static_assert(sizeof(Float) == 4 || sizeof(Float) == 8);
  if constexpr (sizeof(Float) == 4) {
    return std::bit_cast<Float>(LoadUint32(at));
  } else {
    return std::bit_cast<Float>(LoadUint64(at));
  }
}

std::uint32_t RosMessageReader::ReadUint32(std::string_view field) {
  return LoadUint32(ClaimPrimitive(field, 4, "uint32"));
}

std::int32_t RosMessageReader::ReadInt32(std::string_view field) {
  return std::bit_cast<std::int32_t>(LoadUint32(ClaimPrimitive(field, 4, "int32")));
}

float RosMessageReader::ReadFloat32(std::string_view field) {
  return LoadFloat<float>(ClaimPrimitive(field, 4, "float32"));
}

double RosMessageReader::ReadFloat64(std::string_view field) {
  return LoadFloat<double>(ClaimPrimitive(field, 8, "float64"));
}

std::string RosMessageReader::ReadString(std::string_view field) {
  const std::uint32_t length = LoadUint32(ClaimPrimitive(field, 4, "string length (uint32)"));
  const std::size_t at = offset_;
  if (!Fits(at, length)) {
    Fail(field, "a string of length " + std::to_string(length) + " needs " + std::to_string(length) + " bytes", at);
  }
  offset_ = at + length;
  const auto* chars = reinterpret_cast<const char*>(data_.data() + at);
  if (format_ == RosWireFormat::kRos1) return std::string(chars, length);
  // CDR: the length counts the terminating NUL, which must be there.
  if (length == 0) Fail(field, "a CDR string length of 0 leaves no room for the terminating NUL", at);
  if (chars[length - 1] != '\0') {
    Fail(field, "a CDR string of length " + std::to_string(length) + " does not end with a NUL", at);
  }
  return std::string(chars, length - 1);
}

template <typename Float>
std::vector<Float> RosMessageReader::ReadFloatSequence(std::string_view field) {
  const std::uint32_t count = ReadUint32(field);
  const char* name = sizeof(Float) == 4 ? "float32" : "float64";
  const std::size_t at = ClaimElements(field, sizeof(Float), count, name);  // before any allocation
  std::vector<Float> values(count);
  for (std::size_t i = 0; i < count; ++i) values[i] = LoadFloat<Float>(at + sizeof(Float) * i);
  return values;
}

std::vector<float> RosMessageReader::ReadFloat32Sequence(std::string_view field) {
  return ReadFloatSequence<float>(field);
}

std::vector<double> RosMessageReader::ReadFloat64Sequence(std::string_view field) {
  return ReadFloatSequence<double>(field);
}

void RosMessageReader::ReadFloat64Array(std::string_view field, std::span<double> out) {
  const std::size_t at = ClaimElements(field, 8, out.size(), "float64");
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = LoadFloat<double>(at + 8 * i);
}

std::uint32_t RosMessageReader::ReadSequenceCount(std::string_view field, std::size_t min_element_bytes) {
  SLAMTUNE_CHECK(min_element_bytes > 0);
  const std::uint32_t count = ReadUint32(field);
  const std::uint64_t bytes = std::uint64_t{count} * min_element_bytes;
  if (bytes > data_.size() - offset_) {
    Fail(field,
         std::to_string(count) + " elements of at least " + std::to_string(min_element_bytes) + " bytes need " +
             std::to_string(bytes) + " bytes",
         offset_);
  }
  return count;
}

RosHeader RosMessageReader::ReadHeader() {
  RosHeader header;
  std::int64_t sec = 0;
  std::uint32_t nsec = 0;
  if (format_ == RosWireFormat::kRos1) {
    header.seq = ReadUint32("header.seq");
    sec = ReadUint32("header.stamp.sec");  // ROS 1 time: uint32 secs, uint32 nsecs
    nsec = ReadUint32("header.stamp.nsec");
  } else {
    sec = ReadInt32("header.stamp.sec");  // builtin_interfaces/Time: int32 sec, uint32 nanosec
    nsec = ReadUint32("header.stamp.nanosec");
  }
  // |sec| < 2^32 and nsec < 2^32, so the sum stays far inside int64.
  header.stamp_ns = sec * kNanosecondsPerSecond + std::int64_t{nsec};
  header.frame_id = ReadString("header.frame_id");
  return header;
}

}  // namespace slamtune::io
