// Freiburg relations files (io/relations.h), read from a file as the CLI reads them.
#include "fuzz_files.h"
#include "slamtune/common/error.h"
#include "slamtune/io/relations.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string path = slamtune::fuzz::WriteTempFile("relations.txt", slamtune::fuzz::AsText(data, size));
  try {
    slamtune::io::ReadRelations(path);
  } catch (const slamtune::InputError&) {
  }
  return 0;
}
