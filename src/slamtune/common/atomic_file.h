// Output files written whole or not at all: the content goes to FILE.partial beside the target,
// is flushed and checked, then renamed over FILE (rename is atomic within a file system), so a
// reader, an interruption or a full disk never leaves half a file under the final name.
#pragma once

#include <string>
#include <string_view>

namespace slamtune {

// Throws InputError "PATH: cannot write (reason)" and removes the partial file on failure.
void WriteFileAtomically(const std::string& path, std::string_view content);

}  // namespace slamtune
