// The output folder of a command (`--out DIR`), checked before any work is done.
//
// Why: std::filesystem::create_directories throws a filesystem_error whose text names no option
// and exits 1; an existing file, a path under /proc or '' must instead be one InputError line
// and exit 2, and a folder that cannot be written must be found before a long run, not after.
#pragma once

#include <string>

namespace slamtune {

// Creates `dir` (and its parents) if needed and checks that a file can be created in it.
// Throws InputError: "--out: empty folder name" for '', "DIR: cannot create output folder:
// REASON" (REASON "is a file" when DIR names an existing file), "DIR: output folder is not
// writable: REASON".
void EnsureOutputDir(const std::string& dir);

}  // namespace slamtune
