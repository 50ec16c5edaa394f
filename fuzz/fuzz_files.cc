#include "fuzz_files.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <system_error>

namespace slamtune::fuzz {
namespace {

namespace fs = std::filesystem;

// One folder per process, so that parallel fuzzing jobs do not share files.
class TempFolder {
 public:
  TempFolder() {
    std::error_code ec;
    fs::path base = fs::temp_directory_path(ec);
    if (ec) base = "/tmp";
    path_ = base / ("slamtune-fuzz-" + std::to_string(::getpid()));
    fs::create_directories(path_, ec);
    if (ec) {
      std::fprintf(stderr, "fuzz: cannot create %s: %s\n", path_.c_str(), ec.message().c_str());
      std::abort();
    }
  }
  ~TempFolder() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  const fs::path& path() const { return path_; }

 private:
  fs::path path_;
};

}  // namespace

std::string WriteTempFile(const std::string& file_name, std::string_view bytes) {
  static TempFolder folder;
  const fs::path path = folder.path() / file_name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  out.close();
  if (!out) {
    std::fprintf(stderr, "fuzz: cannot write %s\n", path.c_str());
    std::abort();
  }
  return path.string();
}

}  // namespace slamtune::fuzz
