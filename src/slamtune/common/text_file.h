// Whole-file reading of small inputs (parameter YAML, search spaces, map YAML and images, rosbag2
// metadata), so that every reader refuses the same bad paths with the same one-line error.
//
// Why one helper: std::ifstream opens a directory without complaint on Linux and then reads
// it as an empty file or throws `basic_filebuf::underflow` naming no file; a UTF-8 byte-order
// mark written by Windows editors breaks the first key or record. ReadTextFile refuses
// directories and unreadable paths up front and strips the mark.
#pragma once

#include <string>
#include <string_view>

namespace slamtune {

inline constexpr std::string_view kUtf8Bom = "\xEF\xBB\xBF";

// `text` without a leading UTF-8 byte-order mark (EF BB BF), if it has one.
std::string_view StripUtf8Bom(std::string_view text);

// The whole content of the file at `path`, byte for byte. Throws InputError(path, 0, ...) with
// "cannot open: is a directory", "cannot open: no such file", "cannot open: <reason>" (e.g.
// permission denied) or "cannot read: <reason>"; an empty path is an InputError too.
std::string ReadWholeFile(const std::string& path);

// ReadWholeFile without a leading UTF-8 byte-order mark: for every text input.
std::string ReadTextFile(const std::string& path);

}  // namespace slamtune
