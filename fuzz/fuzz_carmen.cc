// CARMEN log text (plain or gzip), strict and lenient (io/carmen/carmen_reader.h).
#include <sstream>
#include <string>

#include "fuzz_files.h"
#include "slamtune/common/error.h"
#include "slamtune/io/carmen/carmen_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  for (const bool lenient : {false, true}) {
    slamtune::io::LogReadOptions options;
    options.lenient = lenient;
    std::istringstream in{std::string(slamtune::fuzz::AsText(data, size))};
    try {
      slamtune::io::ReadCarmenLog(in, "fuzz.log", options);
    } catch (const slamtune::InputError&) {
    }
  }
  return 0;
}
