// The content of an input file (or of a folder's files) as a CRC-32, so that a file changed in
// place, even to the same size and modification time, is noticed (optimize --resume).
//
// CRC-32 (zlib) is not a cryptographic hash: it finds edits and corruption, not forgery.
#pragma once

#include <map>
#include <string>

namespace slamtune::io {

// "crc32:xxxxxxxx" (8 lowercase hex digits) of the file at `path`; for a folder (a ROS 2 bag),
// of the names and contents of its regular files in name order. Throws InputError naming the
// path when it cannot be read.
std::string ContentHash(const std::string& path);

// ContentHash of each named file ("log" -> path), files with an empty path left out.
std::map<std::string, std::string> ContentHashes(const std::map<std::string, std::string>& files);

// Checks each named file of `files` whose name `recorded` holds against the recorded hash;
// names without a recorded hash are not checked (records made before hashes were kept).
// Throws InputError "PATH: changed since the run started (content crc32:..., recorded
// crc32:...); ..." for the first file that differs.
void RequireSameContent(const std::map<std::string, std::string>& recorded,
                        const std::map<std::string, std::string>& files);

}  // namespace slamtune::io
