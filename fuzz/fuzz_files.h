// Shared pieces of the fuzz targets: the input written to a file for readers that take a path,
// and the rule every target follows (InputError is the expected answer to bad bytes; any other
// exception escapes and libFuzzer reports it, as it reports crashes, leaks and UB).
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace slamtune::fuzz {

// The fuzz input as text.
inline std::string_view AsText(const std::uint8_t* data, std::size_t size) {
  return {reinterpret_cast<const char*>(data), size};
}

// A folder of this process under the system temp folder (removed at exit); `file_name` inside
// it is (over)written with `bytes` and its path returned.
std::string WriteTempFile(const std::string& file_name, std::string_view bytes);

}  // namespace slamtune::fuzz
