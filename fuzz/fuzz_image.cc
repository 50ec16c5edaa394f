// PGM (P2/P5) and PNG decoding (io/image_codec.h), in memory.
#include "fuzz_files.h"
#include "slamtune/common/error.h"
#include "slamtune/io/image_codec.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    slamtune::io::DecodeGreyImage(slamtune::fuzz::AsText(data, size), "fuzz.img", "");
  } catch (const slamtune::InputError&) {
  }
  return 0;
}
