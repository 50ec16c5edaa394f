// Structured fuzz inputs: a target that builds objects (a tf tree, a recording's decoded
// contents) rather than parsing a file takes its choices from the input one byte at a time.
// Every byte pattern is a valid program, so the fuzzer spends its time on the code under test,
// not on a format; an input that runs out reads zeros. Numbers come from small tables that
// include the values readers must survive: NaN, +-inf, huge and tiny magnitudes.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace slamtune::fuzz {

class FuzzInput {
 public:
  FuzzInput(const std::uint8_t* data, std::size_t size) : data_(data), size_(size) {}

  bool empty() const { return pos_ >= size_; }
  std::uint8_t Byte() { return pos_ < size_ ? data_[pos_++] : 0; }
  bool Bool() { return (Byte() & 1) != 0; }
  // 0 .. n - 1.
  std::size_t Index(std::size_t n) { return n == 0 ? 0 : Byte() % n; }
  std::uint16_t U16() { return static_cast<std::uint16_t>(Byte() | (Byte() << 8)); }
  // A signed 16-bit count of `unit`s.
  std::int64_t Stamp(std::int64_t unit) { return static_cast<std::int16_t>(U16()) * unit; }
  // A double: one of the special values, or a multiple of 0.1 in [-12.7, 12.8].
  double Double() {
    const std::uint8_t b = Byte();
    switch (b) {
      case 0: return std::numeric_limits<double>::quiet_NaN();
      case 1: return std::numeric_limits<double>::infinity();
      case 2: return -std::numeric_limits<double>::infinity();
      case 3: return 1e300;
      case 4: return -1e300;
      case 5: return 1e-300;
      case 6: return std::numeric_limits<double>::denorm_min();
      default: return (static_cast<int>(b) - 127) / 10.0;
    }
  }
  // One of `names`.
  const std::string& Name(const std::vector<std::string>& names) { return names[Index(names.size())]; }

 private:
  const std::uint8_t* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
};

}  // namespace slamtune::fuzz
